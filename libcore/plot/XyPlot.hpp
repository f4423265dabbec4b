// Line and scatter plots drawn with cairo (SVG or PNG, chosen by the file extension), for the
// ballistic limit curves of ble-size and the histories of hvi-assess.
//
// Deliberately small: linear or logarithmic axes with "nice" ticks, lines, filled or open
// markers, a legend.
// Written atomically like every output (temporary name, then rename).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace hvi::plot {

struct Rgb {
    double r = 0.0, g = 0.0, b = 0.0;
};

struct Series {
    std::string label;
    std::vector<double> x, y;
    Rgb color;
    bool line = true;         ///< a polyline; false draws markers
    bool filledMarker = true; ///< markers only: filled disc or open circle
    double width = 1.5;       ///< line width or marker radius [pt]
};

struct XyPlot {
    std::string title;
    std::string xLabel, yLabel;
    std::vector<Series> series;
    double width = 720, height = 480; ///< [pt]
    /// Axis ranges; NaN = from the data.
    double xMin, xMax, yMin, yMax;
    /// Logarithmic axes (ticks at 1, 2, 5 x 10^k; points with a value <= 0 are left out).
    bool xLog = false, yLog = false;
    XyPlot();
};

/// Writes the plot to `path` (.svg or .png). Throws RuntimeFailure on I/O or cairo errors and
/// InputError for an unknown extension.
void writePlot(const XyPlot& plot, const std::string& path);

/// "Nice" tick positions (1, 2, 5 x 10^k steps) covering [lo, hi] with about `target` ticks.
std::vector<double> niceTicks(double lo, double hi, int target = 6);

/// Ticks of a logarithmic axis over [lo, hi] (data units, > 0): the decades, and 2 and 5
/// times them when the range spans less than three decades.
std::vector<double> logTicks(double lo, double hi);

} // namespace hvi::plot
