// The convergence study's report (validation/ConvergenceReport.hpp) from hand-written verdicts
// of a four-spacing ladder whose bumper hole follows f(h) = 6.9 - 40 h^2 exactly: the order
// and estimate it must print, the errors against them and against the measured 6.7 mm, the
// CSV in spacing order, and the source study's own table for its case only.
#include "TestPaths.hpp"
#include "core/Error.hpp"
#include "validation/ConvergenceReport.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace hvi;
namespace fs = std::filesystem;

namespace {

double holeAt(double h) {
    return 6.9 - 40.0 * h * h;
}

fs::path writeLadder(const std::string& name) {
    const fs::path out = test::tempPath(name);
    fs::remove_all(out);
    for (double h : {0.02, 0.08, 0.04, 0.03}) { // any order on disk
        char dir[32];
        std::snprintf(dir, sizeof dir, "s%g", h);
        fs::create_directories(out / dir);
        const double n = 1.0 / (h * h);
        nlohmann::json v = {{"verdict", "NP"},
                            {"damage_grade", "none"},
                            {"bumper_hole_diameter_mm", holeAt(h)},
                            {"penetration_depth_mm", 1.0},
                            {"energy_error", -1e-3 * h / 0.08},
                            {"wall_time_s", 1e-3 * n / h},
                            {"counts", {{"particles", std::round(n)}, {"elements", 0}}},
                            {"run", {{"steps", std::round(2.0 / h)}}}};
        std::ofstream(out / dir / "verdict.json") << v.dump();
    }
    fs::create_directories(out / "s0.015"); // a point still running: no verdict yet
    fs::create_directories(out / "pictures");
    return out;
}

} // namespace

TEST(ConvergenceReport, OrderEstimateAndErrorsOfAnExactLadder) {
    const auto runs = validation::readLadder(writeLadder("convergence_ladder"));
    ASSERT_EQ(runs.size(), 4u);
    EXPECT_DOUBLE_EQ(runs.front().spacingMm, 0.08);
    EXPECT_DOUBLE_EQ(runs.back().spacingMm, 0.02);

    validation::ConvergenceOptions o;
    o.id = "UM-3.125";
    o.measuredHoleMm = validation::measuredBumperHoleMm("UM-3.125");
    ASSERT_TRUE(o.measuredHoleMm);
    EXPECT_DOUBLE_EQ(*o.measuredHoleMm, 6.7);
    o.sourceStudyMarkdown = validation::sourceStudyTable("UM-3.125");
    const std::string md = validation::convergenceMarkdown(runs, o);
    // p = 2 and f0 = 6.9 exactly; the depth, the same at every spacing, is its own estimate.
    EXPECT_NE(md.find("| bumper hole diameter | 2.00 | 6.900 mm |  |"), std::string::npos) << md;
    EXPECT_NE(md.find("| penetration depth | – | 1.000 mm | the same value at the three finest "
                      "spacings |"),
              std::string::npos)
        << md;
    // 0.02 mm: hole 6.884 mm, 2.7 % above the measured 6.7 mm, 0.2 % below the estimate.
    EXPECT_NE(md.find("| 0.02 | 2500 | 0 | 100 | 125 | 6.88 | 2.7 % | 0.2 % | 1.00 | 0.0 % | NP |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| 0.02 | 6.1 | 11 % | about 1 day |"), std::string::npos) << md;

    const std::string csv = validation::convergenceCsv(runs);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "spacing_mm,sph_particles,fe_elements,steps,wall_time_s,bumper_hole_diameter_mm,"
              "penetration_depth_mm,verdict,damage_grade,energy_error");
    EXPECT_NE(csv.find("\n0.08,156,0,25,2.0,6.6440,1.0000,NP,none,-1.000e-03\n"), std::string::npos)
        << csv;
    EXPECT_LT(csv.find("\n0.08,"), csv.find("\n0.02,")) << "coarsest first";

    // The plot: four series, errors in percent on log-log axes.
    const auto p = validation::convergencePlot(runs, o);
    EXPECT_TRUE(p.xLog && p.yLog);
    ASSERT_EQ(p.series.size(), 4u);
    EXPECT_NEAR(p.series[0].y.back(), 100.0 * (holeAt(0.02) / 6.7 - 1.0), 1e-9);
}

TEST(ConvergenceReport, OnlyTheStudysOwnCaseGetsItsTableAndMeasurement) {
    EXPECT_TRUE(validation::sourceStudyTable("A1076").empty());
    EXPECT_TRUE(validation::sourceStudyPoints("A1076").empty());
    // The study's two timed runs: 0.02 mm, 11 %, a day; 0.015 mm, 3 %, 36 h.
    const auto points = validation::sourceStudyPoints("UM-3.125");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[0], std::make_pair(86400.0, 11.0));
    EXPECT_EQ(points[1], std::make_pair(129600.0, 3.0));
    EXPECT_FALSE(validation::measuredBumperHoleMm("A1076"));
    EXPECT_FALSE(validation::measuredBumperHoleMm("no such case"));
}

TEST(ConvergenceReport, AVerdictWithoutItsFieldsIsRefused) {
    const fs::path out = test::tempPath("convergence_bad");
    fs::remove_all(out);
    fs::create_directories(out / "s0.04");
    std::ofstream(out / "s0.04" / "verdict.json") << R"({"bumper_hole_diameter_mm": 6.0})";
    EXPECT_THROW(validation::readLadder(out), InputError);
}
