// A picture of a 2D axisymmetric state in the (z, r) plane, drawn like the figures of the
// source study: the shot line horizontal (z to the right), the section mirrored about the
// axis (r plotted up and down), equal scales on both axes, a scale bar, a time stamp, and a
// legend of categories or a colour bar. PNG (or SVG by extension), written atomically.
//
// The picture takes world-space primitives (squares for SPH particles, quadrilaterals for
// finite elements) with their colours; what to colour by is the caller's business
// (assess/Pictures.hpp colours by body or by damage).
#pragma once

#include "plot/XyPlot.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace hvi::plot {

/// An SPH particle: a square of side `sizeMm` centred at (z, r).
struct SectionMarker {
    double z = 0.0, r = 0.0, sizeMm = 0.0;
    Rgb color;
};

/// A finite element: a quadrilateral through 4 (z, r) corners.
struct SectionQuad {
    std::array<double, 4> z{}, r{};
    Rgb color;
};

struct LegendEntry {
    std::string label;
    Rgb color;
};

/// A vertical colour bar for a scalar field.
struct ColorBar {
    std::string label;
    double min = 0.0, max = 1.0;
    Rgb (*map)(double t) = nullptr; ///< t in [0, 1]
};

struct SectionPicture {
    std::string title;
    std::string timeStamp;         ///< e.g. "t = 3.000 us", drawn large, top right
    double zMin = 0.0, zMax = 1.0; ///< view along the shot line [mm]
    double rMax = 1.0;             ///< view radius [mm] (the picture shows -rMax..rMax)
    bool mirror = true;            ///< draw r < 0 too (the mirror image)
    int widthPx = 1200, heightPx = 800;
    std::vector<SectionMarker> markers;
    std::vector<SectionQuad> quads;
    std::vector<LegendEntry> legend;
    std::optional<ColorBar> colorBar;
};

/// Writes the picture to `path` (.png or .svg). Throws RuntimeFailure on cairo or I/O errors,
/// InputError for another extension.
void writeSectionPicture(const SectionPicture& picture, const std::string& path);

/// A "nice" scale-bar length (1, 2 or 5 x 10^k mm) close to `target` [mm].
double niceLength(double target);

} // namespace hvi::plot
