// The line plots (plot/XyPlot.hpp): tick placement on linear and logarithmic axes, and a
// log-log plot with values an axis cannot show (zero, negative, NaN) written without them.
#include "TestPaths.hpp"
#include "core/Error.hpp"
#include "plot/XyPlot.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <limits>

using namespace hvi;

TEST(XyPlot, NiceTicksAreRoundStepsCoveringTheRange) {
    EXPECT_EQ(plot::niceTicks(0.0, 10.0, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
    EXPECT_EQ(plot::niceTicks(1.3, 4.1, 3), (std::vector<double>{2, 3, 4}));
}

TEST(XyPlot, LogTicksAreDecadesAndTwoAndFiveTimesThemOverAShortRange) {
    EXPECT_EQ(plot::logTicks(1e-4, 1e2), (std::vector<double>{1e-4, 1e-3, 1e-2, 1e-1, 1, 10, 100}));
    const auto t = plot::logTicks(30.0, 2000.0);
    ASSERT_EQ(t.size(), 6u);
    const double expected[] = {50, 100, 200, 500, 1000, 2000};
    for (std::size_t k = 0; k < t.size(); ++k) {
        EXPECT_NEAR(t[k], expected[k], 1e-9 * expected[k]);
    }
    EXPECT_TRUE(plot::logTicks(0.0, 1.0).empty());
}

TEST(XyPlot, LogLogPlotLeavesOutWhatTheAxesCannotShow) {
    plot::XyPlot p;
    p.title = "error against run time";
    p.xLog = p.yLog = true;
    plot::Series s;
    s.label = "hole";
    s.x = {10, 100, 1000, 0, 50};
    s.y = {0.2, 0.05, 0.01, 0.1, -1};
    p.series.push_back(s);
    plot::Series nan;
    nan.x = {std::numeric_limits<double>::quiet_NaN()};
    nan.y = {1.0};
    nan.line = false;
    p.series.push_back(nan);
    for (const char* ext : {".png", ".svg"}) {
        const auto path = test::tempPath(std::string("xyplot_loglog") + ext);
        std::filesystem::remove(path);
        plot::writePlot(p, path.string());
        ASSERT_TRUE(std::filesystem::exists(path)) << ext;
        EXPECT_GT(std::filesystem::file_size(path), 1000u) << ext;
    }
    EXPECT_THROW(plot::writePlot(p, test::tempPath("xyplot.pdf").string()), InputError);
}
