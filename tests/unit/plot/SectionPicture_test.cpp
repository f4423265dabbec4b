// The mirrored (z, r) section picture (plot/SectionPicture.hpp): pixel size, equal scales,
// the mirror image below the axis, and the scale-bar length rule.
#include "TestPaths.hpp"
#include "core/Error.hpp"
#include "plot/Colormap.hpp"
#include "plot/SectionPicture.hpp"

#include <cairo.h>
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>

using namespace hvi;

namespace {

struct Pixel {
    int r, g, b;
};

Pixel pixelAt(cairo_surface_t* s, int x, int y) {
    const unsigned char* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    std::uint32_t v;
    std::memcpy(&v, data + y * stride + 4 * x, 4);
    return {static_cast<int>((v >> 16) & 0xff), static_cast<int>((v >> 8) & 0xff),
            static_cast<int>(v & 0xff)};
}

} // namespace

TEST(SectionPicture, NiceLengths) {
    EXPECT_EQ(plot::niceLength(1.52), 2.0);
    EXPECT_EQ(plot::niceLength(0.3), 0.2);
    EXPECT_EQ(plot::niceLength(7.0), 10.0);
    EXPECT_EQ(plot::niceLength(-1.0), 1.0);
}

TEST(SectionPicture, MarkerAndItsMirrorImage) {
    // View z in [0, 1], r in [-1, 1] on 400 x 300 px: margins 70/30/56/62 leave 300 x 182,
    // so the scale is 91 px/mm, the 91 x 182 px frame starts at x = 174.5, y = 56.
    plot::SectionPicture pic;
    pic.widthPx = 400;
    pic.heightPx = 300;
    pic.zMin = 0.0;
    pic.zMax = 1.0;
    pic.rMax = 1.0;
    pic.markers.push_back({0.5, 0.5, 0.2, {1.0, 0.0, 0.0}});
    const auto path = test::tempPath("section.png");
    plot::writeSectionPicture(pic, path.string());
    cairo_surface_t* png = cairo_image_surface_create_from_png(path.c_str());
    ASSERT_EQ(cairo_surface_status(png), CAIRO_STATUS_SUCCESS);
    EXPECT_EQ(cairo_image_surface_get_width(png), 400);
    EXPECT_EQ(cairo_image_surface_get_height(png), 300);
    const Pixel above = pixelAt(png, 220, 101); // (z, r) = (0.5, 0.5)
    const Pixel below = pixelAt(png, 220, 192); // (0.5, -0.5): the mirror image
    const Pixel between = pixelAt(png, 220, 130);
    EXPECT_EQ(above.r, 255);
    EXPECT_EQ(above.g, 0);
    EXPECT_EQ(below.r, 255);
    EXPECT_EQ(below.g, 0);
    EXPECT_GT(between.g, 200) << "background between the marker and its image";
    cairo_surface_destroy(png);
}

TEST(SectionPicture, UnknownExtensionIsRejected) {
    plot::SectionPicture pic;
    EXPECT_THROW(plot::writeSectionPicture(pic, test::tempPath("x.jpg").string()), InputError);
}

TEST(Colormap, ViridisEnds) {
    EXPECT_NEAR(plot::viridis(0.0).r, 0.267, 1e-12);
    EXPECT_NEAR(plot::viridis(1.0).g, 0.906, 1e-12);
    EXPECT_NEAR(plot::viridis(2.0).g, 0.906, 1e-12); // clamped
}
