// The stiff and extreme suite (workflows/extreme.mk, validation/StressSuite.hpp) on a CI-sized
// subset: the fastest impact, the thinnest layer (refused before it runs), points on the
// axis, an FE plate struck at 15 km/s. Each must end cleanly with finite fields or be refused
// with its pointer, and the table must say so; a field made NaN in a run file is found.
#include "AssessScenes.hpp"
#include "RunTool.hpp"
#include "TestPaths.hpp"
#include "validation/StressSuite.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace hvi;
using namespace hvi::test;
namespace fs = std::filesystem;

TEST(ExtremeSuite, SubsetEndsCleanlyAndTheTableSaysSo) {
    const fs::path out = tempPath("extreme");
    fs::remove_all(out);
    const fs::path log = out.string() + ".log";
    const std::string make = "make -s -C " + sourcePath("workflows").string() +
                             " extreme ONLY='v30_0 layer_1_point points_on_axis v15_fe' BIN=" +
                             toolPath("hvi-run").parent_path().parent_path().string() +
                             " OUT=" + out.string() + " >" + log.string() + " 2>&1";
    ASSERT_EQ(std::system(make.c_str()), 0);
    std::ifstream in(out / "extreme.md");
    std::stringstream text;
    text << in.rdbuf();
    const std::string md = text.str();
    EXPECT_NE(md.find("4 of 4 ended cleanly"), std::string::npos) << md;
    EXPECT_NE(md.find("| v30_0 | 1 mm Al sphere at 30 km/s on a 0.5 mm Al plate (SPH) | end_time | "
                      "yes |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("/bodies/1/shape: thinner than two particle spacings"), std::string::npos)
        << md;
    EXPECT_EQ(md.find(out.string()), std::string::npos) << "no machine path in the table";
    const auto runs = validation::readStressRuns(out);
    ASSERT_EQ(runs.size(), 4u);
    for (const auto& r : runs) {
        if (r.status == "complete") {
            ASSERT_TRUE(r.minDtUs) << r.name;
            EXPECT_GT(*r.minDtUs, 0.0) << r.name;
            EXPECT_FALSE(r.minDtLimiter.empty()) << r.name;
        }
    }
}

TEST(ExtremeSuite, ANonFiniteFieldIsNamed) {
    SyntheticRun run(whippleScene());
    auto& snap = run.addSnapshot(1.0);
    snap.pressure[3] = std::nan("");
    const auto path = run.write(tempPath("extreme_nan.h5"));
    EXPECT_EQ(validation::firstNonFiniteField(path), "particles/Pressure");
    SyntheticRun clean(whippleScene());
    clean.addSnapshot(1.0);
    EXPECT_EQ(validation::firstNonFiniteField(clean.write(tempPath("extreme_clean.h5"))), "");
}
