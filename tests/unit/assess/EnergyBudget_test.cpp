// Energy error and conservation figures from /history (assess/EnergyBudget.hpp).
#include "AssessScenes.hpp"
#include "assess/EnergyBudget.hpp"

#include <gtest/gtest.h>
#include <limits>

using namespace hvi;

TEST(EnergyBudget, WorstRowIsTheEnergyError) {
    // SyntheticRun's history: errors 0, 1e-4, -3e-3 (at 1 us), 3e-4, 4e-4.
    test::SyntheticRun run(test::whippleScene());
    run.addSnapshot(1.0);
    const auto a = test::assessSynthetic(run, "energy_worst");
    ASSERT_TRUE(a.energy.maxError);
    EXPECT_EQ(*a.energy.maxError, -3.0e-3);
    EXPECT_EQ(*a.energy.maxErrorTimeUs, 1.0);
    EXPECT_EQ(*a.energy.finalError, 4.0e-4);
    EXPECT_EQ(a.energy.rows, 5u);
}

TEST(EnergyBudget, EmptyHistoryHasNoError) {
    const auto budget = assess::energyBudget(io::HistoryColumns{});
    EXPECT_EQ(budget.rows, 0u);
    EXPECT_FALSE(budget.maxError);
}

TEST(EnergyBudget, NonFiniteRowIsReportedNotHidden) {
    test::SyntheticRun run(test::whippleScene());
    run.history[3].energyError = std::numeric_limits<double>::quiet_NaN();
    const auto a = test::assessSynthetic(run, "energy_nan");
    EXPECT_FALSE(a.energy.maxError);
    EXPECT_EQ(*a.energy.maxErrorTimeUs, 1.5);
    bool warned = false;
    for (const auto& w : a.warnings) {
        warned = warned || w.find("not finite") != std::string::npos;
    }
    EXPECT_TRUE(warned);
}
