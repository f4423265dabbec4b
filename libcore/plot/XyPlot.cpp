#include "plot/XyPlot.hpp"

#include "core/Error.hpp"
#include "io/AtomicOutput.hpp"

#include <algorithm>
#include <cairo-svg.h>
#include <cairo.h>
#include <cmath>
#include <cstdio>
#include <limits>

namespace hvi::plot {

XyPlot::XyPlot()
    : xMin(std::numeric_limits<double>::quiet_NaN()),
      xMax(std::numeric_limits<double>::quiet_NaN()),
      yMin(std::numeric_limits<double>::quiet_NaN()),
      yMax(std::numeric_limits<double>::quiet_NaN()) {}

std::vector<double> niceTicks(double lo, double hi, int target) {
    std::vector<double> ticks;
    if (!(hi > lo)) {
        return {lo};
    }
    const double raw = (hi - lo) / std::max(target, 1);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double f : {1.0, 2.0, 5.0, 10.0}) {
        step = f * mag;
        if (step >= raw) {
            break;
        }
    }
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
        ticks.push_back(std::fabs(t) < 1e-12 * step ? 0.0 : t);
    }
    return ticks;
}

std::vector<double> logTicks(double lo, double hi) {
    std::vector<double> ticks;
    if (!(lo > 0.0) || !(hi >= lo)) {
        return ticks;
    }
    const int k0 = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
    const int k1 = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
    const bool fine = std::log10(hi / lo) < 3.0;
    for (int k = k0; k <= k1; ++k) {
        for (double m : {1.0, 2.0, 5.0}) {
            const double t = m * std::pow(10.0, k);
            if ((m == 1.0 || fine) && t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) {
                ticks.push_back(t);
            }
        }
    }
    return ticks;
}

namespace {

std::string formatTick(double v, double step) {
    char buf[32];
    const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
    std::snprintf(buf, sizeof buf, "%.*f", std::max(decimals, 0), v);
    return buf;
}

std::string formatLogTick(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

/// The plot in axis units: a logarithmic axis as log10 of the data (non-positive values NaN).
XyPlot toAxisUnits(const XyPlot& plot) {
    auto lg = [](double v) {
        return v > 0.0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
    };
    XyPlot out = plot;
    for (auto& s : out.series) {
        for (double& v : s.x) {
            v = plot.xLog ? lg(v) : v;
        }
        for (double& v : s.y) {
            v = plot.yLog ? lg(v) : v;
        }
    }
    if (plot.xLog) {
        out.xMin = lg(plot.xMin), out.xMax = lg(plot.xMax);
    }
    if (plot.yLog) {
        out.yMin = lg(plot.yMin), out.yMax = lg(plot.yMax);
    }
    return out;
}

/// The axes' ranges in axis units and the frame on the page [pt]: given limits, or the
/// data's (a linear y axis from 0, 5 % headroom; a logarithmic axis padded 5 %).
struct Frame {
    double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;
    double left = 70, right = 20, top = 40, bottom = 55;
    double pw = 0.0, ph = 0.0;
    double X(double x) const { return left + (x - x0) / (x1 - x0) * pw; }
    double Y(double y) const { return top + ph - (y - y0) / (y1 - y0) * ph; }
};

Frame frameOf(const XyPlot& plot, const XyPlot& original) {
    Frame f;
    double x0 = plot.xMin, x1 = plot.xMax, y0 = plot.yMin, y1 = plot.yMax;
    double dx0 = 1e300, dx1 = -1e300, dy0 = 1e300, dy1 = -1e300;
    for (const auto& s : plot.series) {
        for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
            if (std::isfinite(s.x[k]) && std::isfinite(s.y[k])) {
                dx0 = std::min(dx0, s.x[k]);
                dx1 = std::max(dx1, s.x[k]);
                dy0 = std::min(dy0, s.y[k]);
                dy1 = std::max(dy1, s.y[k]);
            }
        }
    }
    if (dx0 > dx1) {
        dx0 = 0.0, dx1 = 1.0, dy0 = 0.0, dy1 = 1.0;
    }
    if (std::isnan(x0))
        x0 = dx0;
    if (std::isnan(x1))
        x1 = dx1;
    if (std::isnan(y0))
        y0 = plot.yLog ? dy0 - 0.05 * (dy1 - dy0) : std::min(0.0, dy0);
    if (std::isnan(y1))
        y1 = dy1 + 0.05 * (dy1 - y0);
    if (plot.xLog && std::isnan(original.xMin)) {
        const double pad = 0.05 * (x1 - x0);
        x0 -= pad, x1 += pad;
    }
    if (x1 <= x0)
        x1 = x0 + 1.0;
    if (y1 <= y0)
        y1 = y0 + 1.0;
    f.x0 = x0, f.x1 = x1, f.y0 = y0, f.y1 = y1;
    f.pw = plot.width - f.left - f.right;
    f.ph = plot.height - f.top - f.bottom;
    return f;
}

/// Tick positions in axis units, with their labels.
std::vector<std::pair<double, std::string>> ticksOf(bool log, double lo, double hi) {
    std::vector<std::pair<double, std::string>> out;
    if (log) {
        for (double t : logTicks(std::pow(10.0, lo), std::pow(10.0, hi))) {
            out.emplace_back(std::log10(t), formatLogTick(t));
        }
        return out;
    }
    const auto t = niceTicks(lo, hi);
    const double step = t.size() > 1 ? t[1] - t[0] : 1.0;
    for (double v : t) {
        out.emplace_back(v, formatTick(v, step));
    }
    return out;
}

/// Grid lines with their tick labels, and the frame.
void drawGrid(cairo_t* cr, const XyPlot& plot, const Frame& f) {
    cairo_set_font_size(cr, 11);
    const auto xt = ticksOf(plot.xLog, f.x0, f.x1), yt = ticksOf(plot.yLog, f.y0, f.y1);
    cairo_set_line_width(cr, 0.5);
    for (const auto& [t, label] : xt) {
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_move_to(cr, f.X(t), f.top);
        cairo_line_to(cr, f.X(t), f.top + f.ph);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_text_extents_t ext;
        cairo_text_extents(cr, label.c_str(), &ext);
        cairo_move_to(cr, f.X(t) - ext.width / 2, f.top + f.ph + 16);
        cairo_show_text(cr, label.c_str());
    }
    for (const auto& [t, label] : yt) {
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_move_to(cr, f.left, f.Y(t));
        cairo_line_to(cr, f.left + f.pw, f.Y(t));
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_text_extents_t ext;
        cairo_text_extents(cr, label.c_str(), &ext);
        cairo_move_to(cr, f.left - ext.width - 6, f.Y(t) + ext.height / 2);
        cairo_show_text(cr, label.c_str());
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, f.left, f.top, f.pw, f.ph);
    cairo_stroke(cr);
}

/// The axis labels and the title.
void drawLabels(cairo_t* cr, const XyPlot& plot, const Frame& f) {
    cairo_set_font_size(cr, 13);
    cairo_text_extents_t ext;
    cairo_text_extents(cr, plot.xLabel.c_str(), &ext);
    cairo_move_to(cr, f.left + f.pw / 2 - ext.width / 2, plot.height - 14);
    cairo_show_text(cr, plot.xLabel.c_str());
    cairo_save(cr);
    cairo_text_extents(cr, plot.yLabel.c_str(), &ext);
    cairo_move_to(cr, 18, f.top + f.ph / 2 + ext.width / 2);
    cairo_rotate(cr, -M_PI / 2);
    cairo_show_text(cr, plot.yLabel.c_str());
    cairo_restore(cr);
    cairo_set_font_size(cr, 14);
    cairo_text_extents(cr, plot.title.c_str(), &ext);
    cairo_move_to(cr, f.left + f.pw / 2 - ext.width / 2, 24);
    cairo_show_text(cr, plot.title.c_str());
}

/// The series, clipped to the frame: lines broken at non-finite points, or markers.
void drawSeries(cairo_t* cr, const XyPlot& plot, const Frame& f) {
    cairo_save(cr);
    cairo_rectangle(cr, f.left, f.top, f.pw, f.ph);
    cairo_clip(cr);
    for (const auto& s : plot.series) {
        cairo_set_source_rgb(cr, s.color.r, s.color.g, s.color.b);
        const std::size_t n = std::min(s.x.size(), s.y.size());
        if (s.line) {
            cairo_set_line_width(cr, s.width);
            bool pen = false;
            for (std::size_t k = 0; k < n; ++k) {
                if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) {
                    pen = false;
                    continue;
                }
                pen ? cairo_line_to(cr, f.X(s.x[k]), f.Y(s.y[k]))
                    : cairo_move_to(cr, f.X(s.x[k]), f.Y(s.y[k]));
                pen = true;
            }
            cairo_stroke(cr);
        } else {
            cairo_set_line_width(cr, 1.2);
            for (std::size_t k = 0; k < n; ++k) {
                if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) {
                    continue;
                }
                cairo_new_sub_path(cr);
                cairo_arc(cr, f.X(s.x[k]), f.Y(s.y[k]), std::max(s.width, 3.0), 0, 2 * M_PI);
                s.filledMarker ? cairo_fill(cr) : cairo_stroke(cr);
            }
        }
    }
    cairo_restore(cr);
}

/// The legend, top right inside the frame.
void drawLegend(cairo_t* cr, const XyPlot& plot, const Frame& f) {
    cairo_set_font_size(cr, 11);
    cairo_text_extents_t ext;
    double ly = f.top + 16;
    for (const auto& s : plot.series) {
        if (s.label.empty()) {
            continue;
        }
        cairo_text_extents(cr, s.label.c_str(), &ext);
        const double lx = f.left + f.pw - ext.width - 40;
        cairo_set_source_rgb(cr, s.color.r, s.color.g, s.color.b);
        if (s.line) {
            cairo_set_line_width(cr, s.width);
            cairo_move_to(cr, lx, ly - 4);
            cairo_line_to(cr, lx + 24, ly - 4);
            cairo_stroke(cr);
        } else {
            cairo_new_sub_path(cr);
            cairo_arc(cr, lx + 12, ly - 4, 4, 0, 2 * M_PI);
            s.filledMarker ? cairo_fill(cr) : cairo_stroke(cr);
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, lx + 30, ly);
        cairo_show_text(cr, s.label.c_str());
        ly += 16;
    }
}

void draw(cairo_t* cr, const XyPlot& original) {
    const XyPlot plot = toAxisUnits(original);
    const Frame frame = frameOf(plot, original);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    drawGrid(cr, plot, frame);
    drawLabels(cr, plot, frame);
    drawSeries(cr, plot, frame);
    drawLegend(cr, plot, frame);
}

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

void writePlot(const XyPlot& plot, const std::string& path) {
    const bool svg = endsWith(path, ".svg");
    const bool png = endsWith(path, ".png");
    if (!svg && !png) {
        throw InputError("<flags>", "", "plot file '" + path + "' has an unknown extension",
                         ".svg or .png");
    }
    io::AtomicOutput output(path);
    const std::string tmp = output.tempPath().string();
    cairo_surface_t* surface =
        svg ? cairo_svg_surface_create(tmp.c_str(), plot.width, plot.height)
            : cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(plot.width),
                                         static_cast<int>(plot.height));
    cairo_t* cr = cairo_create(surface);
    draw(cr, plot);
    cairo_destroy(cr);
    cairo_status_t status = CAIRO_STATUS_SUCCESS;
    if (png) {
        status = cairo_surface_write_to_png(surface, tmp.c_str());
    }
    cairo_surface_finish(surface);
    if (status == CAIRO_STATUS_SUCCESS) {
        status = cairo_surface_status(surface);
    }
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS) {
        throw RuntimeFailure("cannot draw " + path + ": " + cairo_status_to_string(status));
    }
    output.commit();
}

} // namespace hvi::plot
