// solver/TimeBins: the bin a vote takes, when intervals open and close, the prediction
// offsets, the wake-up and the guard against a growing base step, against hand-worked
// sequences (cfl 1 so a vote is its own limit).
#include "solver/TimeBins.hpp"

#include <gtest/gtest.h>
#include <limits>
#include <vector>

using hvi::solver::TimeBins;

namespace {

std::vector<int32_t> all(std::size_t n) {
    std::vector<int32_t> items(n);
    for (std::size_t i = 0; i < n; ++i) {
        items[i] = static_cast<int32_t>(i);
    }
    return items;
}

} // namespace

TEST(TimeBins, LevelIsTheLongestPowerOfTwoWithinTheLimit) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(TimeBins::levelFor(0.3, 1.0, 0.1, 6), 1); // limit 0.3: 0.2 fits, 0.4 not
    EXPECT_EQ(TimeBins::levelFor(1.0, 4.0, 1.0, 6), 2); // exactly 4 base steps
    EXPECT_EQ(TimeBins::levelFor(1.0, 3.99, 1.0, 6), 1);
    EXPECT_EQ(TimeBins::levelFor(1.0, 0.0, 1.0, 6), 0); // never evaluated: the first bin
    EXPECT_EQ(TimeBins::levelFor(1.0, inf, 1.0, 6), 6);
    EXPECT_EQ(TimeBins::levelFor(1.0, inf, 1.0, 3), 3); // the cap
}

TEST(TimeBins, IntervalsCloseAfterTheirStepsWithTheirOffsets) {
    TimeBins bins;
    bins.reset(3);
    const auto items = all(3);
    const std::vector<uint8_t> alive(3, 1);
    bins.setVote(0, 1.0);
    bins.setVote(1, 2.0);
    bins.setVote(2, 4.0);
    const std::vector<std::vector<int32_t>> closing{{0}, {0, 1}, {0}, {0, 1, 2}};
    for (std::size_t step = 0; step < closing.size(); ++step) {
        bins.beginStep(items, alive, 1.0, 1.0);
        EXPECT_EQ(bins.closing(), closing[step]) << "step " << step + 1;
        if (step == 0) {
            EXPECT_EQ(bins.opening(), items);
            EXPECT_DOUBLE_EQ(bins.openingHalf(2), 2.0); // half of 4 base steps
            // The prediction at the step's end: state(t0 + 1) = half + (1 - 2) rate.
            EXPECT_DOUBLE_EQ(bins.predictionOffset(2), -1.0);
            EXPECT_DOUBLE_EQ(bins.predictionOffset(0), 0.5); // closing: half its step
        }
        if (step == 3) {
            EXPECT_FALSE(bins.opening().empty());
            EXPECT_DOUBLE_EQ(bins.interval(2), 4.0);
            EXPECT_TRUE(bins.shortened().empty());
            EXPECT_DOUBLE_EQ(bins.closingHalf(2), 2.0);
        }
        bins.endStep(items, alive, 1.0);
    }
}

TEST(TimeBins, AWokenIntervalClosesAtTheNextStepAndReopensUnderTheCap) {
    TimeBins bins;
    bins.reset(2);
    const auto items = all(2);
    const std::vector<uint8_t> alive(2, 1);
    bins.setVote(0, 1.0);
    bins.setVote(1, 64.0); // level 6
    bins.beginStep(items, alive, 1.0, 1.0);
    bins.wakeNeighbour(1, 0); // an evaluated neighbour in the first bin: at most level 2
    bins.endStep(items, alive, 1.0);
    bins.beginStep(items, alive, 1.0, 1.0);
    ASSERT_EQ(bins.closing(), (std::vector<int32_t>{0, 1}));
    EXPECT_DOUBLE_EQ(bins.interval(1), 2.0);
    EXPECT_EQ(bins.shortened(), (std::vector<int32_t>{1}));
    EXPECT_DOUBLE_EQ(bins.closingCorrection(1), 0.5 * (2.0 - 64.0));
    bins.endStep(items, alive, 1.0);
    // It reopens at level 2 (4 steps) although its vote allows 64.
    for (int k = 0; k < 3; ++k) {
        bins.beginStep(items, alive, 1.0, 1.0);
        EXPECT_EQ(bins.closing(), (std::vector<int32_t>{0})) << k;
        bins.endStep(items, alive, 1.0);
    }
    bins.beginStep(items, alive, 1.0, 1.0);
    EXPECT_EQ(bins.closing(), (std::vector<int32_t>{0, 1}));
    // A neighbour in a bin within reach does not wake it.
    bins.endStep(items, alive, 1.0);
    bins.beginStep(items, alive, 1.0, 1.0);
    bins.wakeNeighbour(1, 5);
    bins.endStep(items, alive, 1.0);
    bins.beginStep(items, alive, 1.0, 1.0);
    EXPECT_EQ(bins.closing(), (std::vector<int32_t>{0}));
}

TEST(TimeBins, AGrowingBaseStepClosesAnIntervalBeforeItsLimit) {
    TimeBins bins;
    bins.reset(1);
    const auto items = all(1);
    const std::vector<uint8_t> alive(1, 1);
    bins.setVote(0, 4.0); // level 2 at a base step of 1: limit 4
    const double dts[] = {1.0, 1.25, 1.5};
    for (int k = 0; k < 3; ++k) {
        bins.beginStep(items, alive, 1.0, dts[k]);
        // Steps 1 and 2 end at 1 and 2.25, each leaving room for one more step of their
        // length; step 3 ends at 3.75, and one more of 1.5 would pass 4.
        EXPECT_EQ(bins.closing().size(), k == 2 ? 1U : 0U) << "step " << k + 1;
        bins.endStep(items, alive, dts[k]);
    }
    bins.beginStep(items, alive, 1.0, 1.0);
    EXPECT_EQ(bins.opening().size(), 1U);
}

TEST(TimeBins, APointNotYetEvolvingIsEvaluatedForOneBaseStep) {
    TimeBins bins;
    bins.reset(2);
    EXPECT_TRUE(bins.evaluated(1));
    bins.admit(1, 0.5);
    EXPECT_DOUBLE_EQ(bins.closingHalf(1), 0.25);
    EXPECT_DOUBLE_EQ(bins.interval(1), 0.5);
}

TEST(TimeBins, APointThatJoinsInTheCourseOfAStepOpensItsIntervalAtTheNext) {
    // Point 1 is dead when the step begins (an unused slot that an eroded element fills
    // during the step) but evolving and alive when it ends: it began no interval, so the end
    // of the step leaves it at the start of one, as a resumed run that counted it evolving
    // all along must find it.
    TimeBins bins;
    bins.reset(2);
    const auto items = all(2);
    std::vector<uint8_t> alive{1, 0};
    bins.setVote(0, 4.0);
    bins.beginStep(items, alive, 1.0, 1.0);
    EXPECT_TRUE(bins.begun(0));
    EXPECT_FALSE(bins.begun(1));
    alive[1] = 1;
    bins.endStep(items, alive, 1.0);
    bins.setVote(1, 4.0);
    bins.beginStep(items, alive, 1.0, 1.0);
    EXPECT_EQ(bins.opening(), std::vector<int32_t>{1}); // point 0 is in its first interval
    EXPECT_DOUBLE_EQ(bins.openingHalf(1), 2.0);         // a whole interval of its own
}
