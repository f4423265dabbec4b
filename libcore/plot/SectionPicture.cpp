#include "plot/SectionPicture.hpp"

#include "core/Error.hpp"
#include "io/AtomicOutput.hpp"

#include <algorithm>
#include <cairo-svg.h>
#include <cairo.h>
#include <cmath>
#include <cstdio>

namespace hvi::plot {

double niceLength(double target) {
    if (!(target > 0.0) || !std::isfinite(target)) {
        return 1.0;
    }
    const double mag = std::pow(10.0, std::floor(std::log10(target)));
    double best = mag;
    for (double f : {1.0, 2.0, 5.0, 10.0}) {
        if (f * mag <= target * 1.5) {
            best = f * mag;
        }
    }
    return best;
}

namespace {

std::string formatNumber(double v, double step) {
    char buf[32];
    const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
    std::snprintf(buf, sizeof buf, "%.*f", std::max(decimals, 0), std::fabs(v) < 1e-12 ? 0.0 : v);
    return buf;
}

void setColor(cairo_t* cr, const Rgb& c) {
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

/// Text with a white box behind it, its left baseline at (x, y).
void boxedText(cairo_t* cr, const std::string& text, double x, double y) {
    cairo_text_extents_t ext;
    cairo_text_extents(cr, text.c_str(), &ext);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_rectangle(cr, x + ext.x_bearing - 4, y + ext.y_bearing - 4, ext.width + 8,
                    ext.height + 8);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, text.c_str());
}

/// The drawing area on the page [px]: the (z, r) section at equal scale on both axes,
/// centred in the space the margins leave.
struct Canvas {
    double left = 70, top = 56;
    double rTop = 0.0, rBottom = 0.0;
    double zMin = 0.0, zSpan = 0.0;
    double scale = 1.0;        ///< px per mm
    double ox = 0.0, oy = 0.0; ///< the frame's top left corner
    double dw = 0.0, dh = 0.0; ///< the frame's size
    double X(double z) const { return ox + (z - zMin) * scale; }
    double Y(double r) const { return oy + (rTop - r) * scale; }
};

Canvas canvasOf(const SectionPicture& pic) {
    Canvas c;
    const double width = pic.widthPx, height = pic.heightPx;
    const bool side = !pic.legend.empty() || pic.colorBar.has_value();
    const double right = side ? 200 : 30, bottom = 62;
    const double pw = std::max(10.0, width - c.left - right);
    const double ph = std::max(10.0, height - c.top - bottom);
    c.zMin = pic.zMin;
    c.zSpan = std::max(pic.zMax - pic.zMin, 1e-9);
    c.rTop = pic.rMax;
    c.rBottom = pic.mirror ? -pic.rMax : 0.0;
    const double rSpan = std::max(c.rTop - c.rBottom, 1e-9);
    c.scale = std::min(pw / c.zSpan, ph / rSpan);
    c.dw = c.zSpan * c.scale;
    c.dh = rSpan * c.scale;
    c.ox = c.left + 0.5 * (pw - c.dw);
    c.oy = c.top + 0.5 * (ph - c.dh);
    return c;
}

/// The material (quads and square markers, mirrored below the axis when asked), clipped to
/// the frame, and the symmetry axis.
void drawMaterial(cairo_t* cr, const SectionPicture& pic, const Canvas& c) {
    cairo_save(cr);
    cairo_rectangle(cr, c.ox, c.oy, c.dw, c.dh);
    cairo_clip(cr);
    cairo_set_source_rgb(cr, 0.97, 0.97, 0.97);
    cairo_paint(cr);
    const int sides = pic.mirror ? 2 : 1;
    // Solid fills: anti-aliased edges of adjacent squares would show the lattice as a grid.
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (const auto& q : pic.quads) {
        setColor(cr, q.color);
        for (int m = 0; m < sides; ++m) {
            const double sign = m == 0 ? 1.0 : -1.0;
            cairo_move_to(cr, c.X(q.z[0]), c.Y(sign * q.r[0]));
            for (int k = 1; k < 4; ++k) {
                cairo_line_to(cr, c.X(q.z[static_cast<std::size_t>(k)]),
                              c.Y(sign * q.r[static_cast<std::size_t>(k)]));
            }
            cairo_close_path(cr);
            cairo_fill(cr);
        }
    }
    for (const auto& p : pic.markers) {
        const double edge = std::max(1.0, p.sizeMm * c.scale);
        setColor(cr, p.color);
        for (int m = 0; m < sides; ++m) {
            const double r = m == 0 ? p.r : -p.r;
            cairo_rectangle(cr, c.X(p.z) - 0.5 * edge, c.Y(r) - 0.5 * edge, edge, edge);
        }
        cairo_fill(cr);
    }
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
    if (pic.mirror) { // the symmetry axis
        cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
        cairo_set_line_width(cr, 0.8);
        const double dash[] = {8.0, 4.0, 2.0, 4.0};
        cairo_set_dash(cr, dash, 4, 0.0);
        cairo_move_to(cr, c.ox, c.Y(0.0));
        cairo_line_to(cr, c.ox + c.dw, c.Y(0.0));
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0.0);
    }
    cairo_restore(cr);
}

/// The frame, its ticks and tick labels, the axis labels and the title.
void drawAxes(cairo_t* cr, const SectionPicture& pic, const Canvas& c) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, c.ox, c.oy, c.dw, c.dh);
    cairo_stroke(cr);
    cairo_set_font_size(cr, 11);
    const auto zt = niceTicks(pic.zMin, pic.zMax, std::max(3, static_cast<int>(c.dw / 90)));
    const auto rt = niceTicks(c.rBottom, c.rTop, std::max(3, static_cast<int>(c.dh / 60)));
    const double zStep = zt.size() > 1 ? zt[1] - zt[0] : 1.0;
    const double rStep = rt.size() > 1 ? rt[1] - rt[0] : 1.0;
    cairo_text_extents_t ext;
    for (double t : zt) {
        cairo_move_to(cr, c.X(t), c.oy + c.dh);
        cairo_line_to(cr, c.X(t), c.oy + c.dh + 5);
        cairo_stroke(cr);
        const std::string label = formatNumber(t, zStep);
        cairo_text_extents(cr, label.c_str(), &ext);
        cairo_move_to(cr, c.X(t) - ext.width / 2, c.oy + c.dh + 18);
        cairo_show_text(cr, label.c_str());
    }
    for (double t : rt) {
        cairo_move_to(cr, c.ox - 5, c.Y(t));
        cairo_line_to(cr, c.ox, c.Y(t));
        cairo_stroke(cr);
        const std::string label = formatNumber(t, rStep);
        cairo_text_extents(cr, label.c_str(), &ext);
        cairo_move_to(cr, c.ox - ext.width - 8, c.Y(t) + ext.height / 2);
        cairo_show_text(cr, label.c_str());
    }
    cairo_set_font_size(cr, 13);
    const std::string zLabel = "z [mm] (shot direction \xe2\x86\x92)";
    cairo_text_extents(cr, zLabel.c_str(), &ext);
    cairo_move_to(cr, c.ox + c.dw / 2 - ext.width / 2, c.oy + c.dh + 40);
    cairo_show_text(cr, zLabel.c_str());
    cairo_save(cr);
    const std::string rLabel = "r [mm]";
    cairo_text_extents(cr, rLabel.c_str(), &ext);
    cairo_move_to(cr, 20, c.oy + c.dh / 2 + ext.width / 2);
    cairo_rotate(cr, -M_PI / 2);
    cairo_show_text(cr, rLabel.c_str());
    cairo_restore(cr);
    cairo_set_font_size(cr, 15);
    cairo_move_to(cr, c.left, 26);
    cairo_show_text(cr, pic.title.c_str());
}

/// The time stamp (top right) and the scale bar (bottom left), inside the frame.
void drawStampAndScale(cairo_t* cr, const SectionPicture& pic, const Canvas& c) {
    cairo_text_extents_t ext;
    if (!pic.timeStamp.empty()) {
        cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
        cairo_set_font_size(cr, 18);
        cairo_text_extents(cr, pic.timeStamp.c_str(), &ext);
        boxedText(cr, pic.timeStamp, c.ox + c.dw - ext.width - 14, c.oy + ext.height + 12);
        cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    }
    const double length = niceLength(0.2 * c.zSpan);
    const double px = length * c.scale;
    const double x0 = c.ox + 16, y0 = c.oy + c.dh - 16;
    char label[32];
    std::snprintf(label, sizeof label, "%g mm", length);
    cairo_set_font_size(cr, 13);
    cairo_text_extents(cr, label, &ext);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_rectangle(cr, x0 - 6, y0 - ext.height - 16, std::max(px, ext.width) + 12,
                    ext.height + 26);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_rectangle(cr, x0, y0 - 5, px, 5);
    cairo_fill(cr);
    cairo_move_to(cr, x0 + px / 2 - ext.width / 2, y0 - 10);
    cairo_show_text(cr, label);
}

/// The legend, then the colour bar if any, right of the frame.
void drawKey(cairo_t* cr, const SectionPicture& pic, const Canvas& c) {
    const double sx = c.ox + c.dw + 24;
    cairo_set_font_size(cr, 12);
    double ly = c.oy + 10;
    for (const auto& entry : pic.legend) {
        setColor(cr, entry.color);
        cairo_rectangle(cr, sx, ly, 14, 14);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, sx + 20, ly + 12);
        cairo_show_text(cr, entry.label.c_str());
        ly += 20;
    }
    if (!pic.colorBar || !pic.colorBar->map) {
        return;
    }
    const auto& bar = *pic.colorBar;
    const double barTop = ly + 24, barHeight = std::max(40.0, 0.6 * c.dh);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, sx, ly + 10);
    cairo_show_text(cr, bar.label.c_str());
    const int steps = 128;
    for (int k = 0; k < steps; ++k) {
        const double t = (k + 0.5) / steps;
        setColor(cr, bar.map(t));
        cairo_rectangle(cr, sx, barTop + barHeight * (1.0 - static_cast<double>(k + 1) / steps), 20,
                        barHeight / steps + 0.5);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_rectangle(cr, sx, barTop, 20, barHeight);
    cairo_stroke(cr);
    const auto ticks = niceTicks(bar.min, bar.max, 5);
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
    for (double t : ticks) {
        const double y = barTop + barHeight * (1.0 - (t - bar.min) / (bar.max - bar.min));
        cairo_move_to(cr, sx + 20, y);
        cairo_line_to(cr, sx + 25, y);
        cairo_stroke(cr);
        const std::string label = formatNumber(t, step);
        cairo_move_to(cr, sx + 29, y + 4);
        cairo_show_text(cr, label.c_str());
    }
}

void draw(cairo_t* cr, const SectionPicture& pic) {
    const Canvas canvas = canvasOf(pic);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    drawMaterial(cr, pic, canvas);
    drawAxes(cr, pic, canvas);
    drawStampAndScale(cr, pic, canvas);
    drawKey(cr, pic, canvas);
}

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

void writeSectionPicture(const SectionPicture& picture, const std::string& path) {
    const bool svg = endsWith(path, ".svg");
    const bool png = endsWith(path, ".png");
    if (!svg && !png) {
        throw InputError("<flags>", "", "picture file '" + path + "' has an unknown extension",
                         ".png or .svg");
    }
    io::AtomicOutput output(path);
    const std::string tmp = output.tempPath().string();
    cairo_surface_t* surface =
        svg ? cairo_svg_surface_create(tmp.c_str(), picture.widthPx, picture.heightPx)
            : cairo_image_surface_create(CAIRO_FORMAT_RGB24, picture.widthPx, picture.heightPx);
    cairo_t* cr = cairo_create(surface);
    draw(cr, picture);
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
