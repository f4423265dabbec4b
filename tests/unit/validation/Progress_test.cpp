// The progress line of `make validate` (validation/Progress.hpp): counts from the verdicts on
// disk, the estimate from their run times in whole rounds of parallel runs, by hand.
#include "TestPaths.hpp"
#include "validation/Progress.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace hvi;

TEST(ValidationProgress, CountsTheVerdictsOnDiskAndAveragesTheirRunTimes) {
    const auto cases = validation::selectCases("quick"); // four cases
    ASSERT_EQ(cases.size(), 4u);
    const auto out = test::tempPath("progress");
    std::filesystem::remove_all(out);
    const double wall[] = {100.0, 300.0};
    for (int k = 0; k < 2; ++k) {
        std::filesystem::create_directories(out / cases[k].id);
        std::ofstream(out / cases[k].id / "verdict.json")
            << "{\"verdict\": \"P\", \"wall_time_s\": " << wall[k] << "}";
    }
    std::filesystem::create_directories(out / cases[2].id); // inputs, no verdict yet
    const auto p = validation::progressOf(cases, out);
    EXPECT_EQ(p.total, 4u);
    EXPECT_EQ(p.done, 2u);
    EXPECT_EQ(p.timed, 2u);
    EXPECT_DOUBLE_EQ(p.meanWallS, 200.0);
    // Two left: one round of 200 s at 2 jobs (3 min), two rounds at 1 job (7 min).
    EXPECT_EQ(validation::progressLine(p, 2),
              "validate: 2/4 cases done, 2 left, about 3 min to go at 2 jobs (mean 200 s a run)");
    EXPECT_EQ(validation::progressLine(p, 1),
              "validate: 2/4 cases done, 2 left, about 7 min to go at 1 job (mean 200 s a run)");
}

TEST(ValidationProgress, HoursSecondsNoEstimateBeforeATimedRunAndTheEnd) {
    validation::Progress p;
    p.total = 116;
    p.done = 14;
    p.timed = 14;
    p.meanWallS = 600.0;
    EXPECT_EQ(validation::progressLine(p, 2), "validate: 14/116 cases done, 102 left, about 8 h "
                                              "30 min to go at 2 jobs (mean 600 s a run)");
    p.meanWallS = 1.0; // 51 rounds of a second
    EXPECT_EQ(validation::progressLine(p, 2), "validate: 14/116 cases done, 102 left, about 51 s "
                                              "to go at 2 jobs (mean 1 s a run)");
    p.timed = 0;
    EXPECT_EQ(validation::progressLine(p, 2), "validate: 14/116 cases done, 102 left");
    p.done = 116;
    EXPECT_EQ(validation::progressLine(p, 2), "validate: all 116 cases done");
}
