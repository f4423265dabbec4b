# Renders one time of a run in ParaView to a PNG: the live particles and elements of the
# run's XDMF sidecar, mirrored about the axis so the picture shows the whole cross-section,
# coloured by one cell field, with its colour bar and the time.
#
#   xvfb-run -a pvpython scripts/render-run.py RUN.xmf OUT.png [FIELD] [TIME_US|last] [RANGE_MIN RANGE_MAX]
#
# FIELD defaults to Density; TIME to the last snapshot; the colour range to the field's range
# at that time. Needs Debian's paraview (scripts/install-deps.sh --paraview). Without a
# display, run it under xvfb-run as above.
import os
import sys

from paraview import simple as pv


def main(argv):
    if len(argv) < 3:
        sys.exit("usage: pvpython render-run.py RUN.xmf OUT.png [FIELD] [TIME_US|last] "
                 "[RANGE_MIN RANGE_MAX]")
    # ParaView 5.11's Xdmf3 readers crash on a bare file name ("run.xmf"): give them a path.
    xmf, picture = os.path.abspath(argv[1]), argv[2]
    field = argv[3] if len(argv) > 3 else "Density"
    reader = pv.XDMFReader(FileNames=[xmf])
    times = list(reader.TimestepValues)
    if not times:
        sys.exit(f"render-run: {xmf}: no time steps")
    when = argv[4] if len(argv) > 4 else "last"
    time = times[-1] if when == "last" else min(times, key=lambda t: abs(t - float(when)))

    # The run is a half-plane r >= 0; its mirror image completes the cross-section.
    mirror = pv.Reflect(Input=reader, Plane="Y Min", CopyInput=1)
    view = pv.CreateRenderView()
    view.ViewSize = [1200, 700]
    view.ViewTime = time
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    display = pv.Show(mirror, view)
    display.Representation = "Surface"
    display.PointSize = 3
    pv.ColorBy(display, ("CELLS", field))
    lut = pv.GetColorTransferFunction(field)
    if len(argv) > 6:
        lut.RescaleTransferFunction(float(argv[5]), float(argv[6]))
    else:
        display.RescaleTransferFunctionToDataRange(False, True)
    display.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = field
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.AutomaticLabelFormat = 0
    bar.LabelFormat = bar.RangeLabelFormat = "%-#.3g"
    label = pv.Text(Text=f"t = {time:.2f} us   (x: shot line z [mm], y: radius r [mm])")
    text = pv.Show(label, view)
    text.Color = [0, 0, 0]
    text.WindowLocation = "Upper Left Corner"
    view.InteractionMode = "2D"
    pv.ResetCamera(view)
    pv.SaveScreenshot(picture, view, ImageResolution=[1200, 700])
    print(f"render-run: {picture}: {field} at t = {time} us")


main(sys.argv)
