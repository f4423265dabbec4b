# Opens a run's XDMF sidecar in a real ParaView, as a user does, and checks what it shows
# against the run file itself (read with h5py, independently of the toolkit's code).
#
#   pvpython check_run_xdmf.py RUN.xmf RUN.h5 PICTURE.png
#
# For ParaView's own reader choice (OpenDataFile), the legacy "XDMF Reader" and "Xdmf3
# Reader T": the time values are the snapshots' times; at every time the blocks hold exactly
# the alive particles, the alive elements and the nodes those elements use; the arrays have the
# ranges of the alive material in the run file; the blocks keep their names and order. Then
# renders the last time coloured by pressure. Exits non-zero on the first mismatch; the CTest
# wrapper also fails on any warning or error a reader prints.
import os
import sys

import h5py
import numpy as np
from paraview import servermanager as sm
from paraview import simple as pv
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet

# The view stores the run file's doubles in single precision (relative rounding 6e-8), and
# ParaView takes vector magnitudes from the rounded components: a few float epsilons.
# Values below single precision's smallest normal number (1.2e-38) read back as 0 or
# subnormal.
RTOL = 1e-6
ATOL = 1.2e-38


def fail(message):
    print("check_run_xdmf: FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def expect_close(what, got, want):
    got, want = np.asarray(got, float), np.asarray(want, float)
    if got.shape != want.shape or not np.all(np.abs(got - want) <= ATOL + RTOL * np.abs(want)):
        fail(f"{what}: ParaView shows {got.tolist()}, the run file {want.tolist()}")


def expected_snapshots(h5_path):
    """Per snapshot: time and, per block, counts and array ranges of the live material."""
    snapshots = []
    with h5py.File(h5_path, "r") as f:
        for name in sorted(f["snapshots"]):
            g = f["snapshots"][name]
            alive = g["Alive"][:] == 1
            vz, vr = g["Vz"][:][alive], g["Vr"][:][alive]
            particles = {
                "points": int(alive.sum()),
                "cells": int(alive.sum()),
                "ranges": {
                    "Density": g["Density"][:][alive],
                    "Pressure": g["Pressure"][:][alive],
                    "Mass": g["Mass"][:][alive],
                    "InternalEnergy": g["InternalEnergy"][:][alive],
                    "Velocity": np.hypot(vz, vr),
                },
                "dead": int((~alive).sum()),
            }
            if "Damage" in g:
                particles["ranges"]["Damage"] = g["Damage"][:][alive]
            if "StressDeviator" in g:
                s = g["StressDeviator"][:][alive]
                particles["ranges"]["StressDeviatorTT"] = -(s[:, 0] + s[:, 1])
            block = {"Particles": particles}
            if "Elements" in g:
                live = g["Elements/Alive"][:] == 1
                conn = g["Elements/Connectivity"][:][live]
                used = np.unique(conn)
                nvz, nvr = g["Nodes/Vz"][:], g["Nodes/Vr"][:]
                cell_vz = nvz[conn].mean(axis=1)
                cell_vr = nvr[conn].mean(axis=1)
                block["FiniteElements"] = {
                    "points": int(used.size),
                    "cells": int(live.sum()),
                    "ranges": {
                        "Density": g["Elements/Density"][:][live],
                        "Pressure": g["Elements/Pressure"][:][live],
                        "NodeVelocity": np.hypot(nvz[used], nvr[used]),
                        "Velocity": np.hypot(cell_vz, cell_vr),
                    },
                    "dead": int((~live).sum()) + int(g["Nodes/Z"].shape[0] - used.size),
                }
            snapshots.append((float(g.attrs["Time"]), block))
    return snapshots


def leaves(data):
    """(name or None, dataset) for every leaf of a composite dataset, in order."""
    out = []

    def walk(node):
        if node.IsA("vtkMultiBlockDataSet"):
            for i in range(node.GetNumberOfBlocks()):
                meta = node.GetMetaData(i)
                child = node.GetBlock(i)
                if child is None:
                    continue
                if child.IsA("vtkDataSet"):
                    name = meta.Get(vtkCompositeDataSet.NAME()) if meta.Has(vtkCompositeDataSet.NAME()) else None
                    out.append((name, child))
                else:
                    walk(child)
        elif node.IsA("vtkMultiPieceDataSet"):
            for i in range(node.GetNumberOfPieces()):
                if node.GetPiece(i) is not None:
                    out.append((None, node.GetPiece(i)))

    walk(data)
    return out


def array_range(dataset, name):
    for attributes in (dataset.GetCellData(), dataset.GetPointData()):
        array = attributes.GetArray(name)
        if array is not None:
            return array.GetRange(-1) if array.GetNumberOfComponents() > 1 else array.GetRange(0)
    return None


def check_reader(label, reader, snapshots, names_expected):
    times = list(reader.TimestepValues)
    expect_close(f"{label}: time values", times, [t for t, _ in snapshots])
    kinds = list(snapshots[0][1].keys())
    for t, blocks in snapshots:
        reader.UpdatePipeline(t)
        found = leaves(sm.Fetch(reader))
        if len(found) != len(kinds):
            fail(f"{label} t={t}: {len(found)} blocks, expected {len(kinds)} ({kinds})")
        for kind, (name, dataset) in zip(kinds, found):
            if names_expected and name != kind:
                fail(f"{label} t={t}: block named {name!r}, expected {kind!r} at every time")
            want = blocks[kind]
            if want["cells"] == 0:
                continue  # nothing alive: one placeholder point, no cells
            if dataset.GetNumberOfPoints() != want["points"]:
                fail(f"{label} t={t} {kind}: {dataset.GetNumberOfPoints()} points, "
                     f"expected {want['points']} (live material only)")
            if dataset.GetNumberOfCells() != want["cells"]:
                fail(f"{label} t={t} {kind}: {dataset.GetNumberOfCells()} cells, "
                     f"expected {want['cells']}")
            for array, values in want["ranges"].items():
                got = array_range(dataset, array)
                if got is None:
                    fail(f"{label} t={t} {kind}: no array {array}")
                expect_close(f"{label} t={t} {kind} {array} range", got,
                             [values.min(), values.max()])
    print(f"check_run_xdmf: {label}: {len(times)} times, blocks {kinds}, counts and ranges match")


def main():
    xmf, h5, picture = sys.argv[1:4]
    # ParaView 5.11's Xdmf3 readers crash on a bare file name ("run.xmf"): give them a path.
    xmf = os.path.abspath(xmf)
    snapshots = expected_snapshots(h5)
    # The check must be able to fail: the run has dead material the view must leave out.
    dead = sum(b[k]["dead"] for _, b in snapshots for k in b)
    if dead == 0:
        fail("the run has no dead material; the check would prove nothing")

    default = pv.OpenDataFile(xmf)
    if default is None:
        fail("ParaView found no reader for " + xmf)
    label = "OpenDataFile -> " + default.GetXMLName()
    # Xdmf3 Reader S reads the blocks as pieces of one dataset; its leaves are the same grids.
    check_reader(label, default, snapshots, names_expected=False)
    check_reader("XDMF Reader", pv.XDMFReader(FileNames=[xmf]), snapshots, names_expected=True)
    check_reader("Xdmf3 Reader T", pv.Xdmf3ReaderT(FileName=[xmf]), snapshots,
                 names_expected=False)

    legacy = pv.XDMFReader(FileNames=[xmf])
    last = snapshots[-1][0]
    if "FiniteElements" in snapshots[-1][1]:
        extract = pv.ExtractBlock(Input=legacy, Selectors=["/Root/FiniteElements"])
        extract.UpdatePipeline(last)
        cells = extract.GetDataInformation().GetNumberOfCells()
        if cells != snapshots[-1][1]["FiniteElements"]["cells"]:
            fail(f"Extract Block /Root/FiniteElements at the last time: {cells} cells")

    view = pv.CreateRenderView()
    view.ViewSize = [800, 500]
    view.ViewTime = last
    display = pv.Show(default, view)
    pv.ColorBy(display, ("CELLS", "Pressure"))
    display.RescaleTransferFunctionToDataRange(True, False)
    pv.ResetCamera(view)
    pv.SaveScreenshot(picture, view, ImageResolution=[800, 500])
    print("check_run_xdmf: rendered " + picture)


main()
