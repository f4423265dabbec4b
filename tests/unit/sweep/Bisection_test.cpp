// The bracketing search against oracles with a known threshold: it must end with the threshold
// inside a bracket no wider than the tolerance, in the number of runs a step-out-then-halve
// search needs, for either direction, and report what it cannot resolve.
#include "sweep/Bisection.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <random>

using namespace hvi::sweep;

namespace {

struct Outcome {
    SearchStep last;
    std::vector<SearchPoint> points;
};

Outcome search(const SearchSettings& s, const std::function<bool(double)>& perforates) {
    Outcome o;
    for (int guard = 0; guard < 100; ++guard) {
        o.last = nextStep(s, o.points);
        if (o.last.state != SearchState::RunNext) {
            return o;
        }
        o.points.push_back({o.last.next, perforates(o.last.next)});
    }
    ADD_FAILURE() << "the search did not stop";
    return o;
}

SearchSettings diameterSearch(double guess) {
    SearchSettings s;
    s.direction = Direction::FailsAsItGrows;
    s.guess = guess;
    s.tolerance = 0.05;
    s.lowest = 0.1;
    s.highest = 20.0;
    return s;
}

} // namespace

TEST(Bisection, BracketsTheThresholdFromAGuessOnEitherSide) {
    const double threshold = 3.37;
    for (const double guess : {2.0, 3.0, 3.37, 4.0, 9.0}) {
        const SearchSettings s = diameterSearch(guess);
        const Outcome o = search(s, [&](double d) { return d >= threshold; });
        ASSERT_EQ(o.last.state, SearchState::Converged) << "guess " << guess;
        ASSERT_TRUE(o.last.failSide && o.last.holdSide);
        EXPECT_GE(*o.last.failSide, threshold);
        EXPECT_LT(*o.last.holdSide, threshold);
        EXPECT_LE(*o.last.failSide - *o.last.holdSide, s.tolerance);
        // Steps out: ceil(log(ratio)/log(1.25)) + 1 runs; then halving from one step's width.
        const double width = std::abs(guess - threshold) * 0.25 + 0.25 * guess;
        const int bound =
            2 +
            static_cast<int>(std::ceil(std::log(std::max(guess / threshold, threshold / guess)) /
                                       std::log(1.25))) +
            static_cast<int>(std::ceil(std::log2(width / s.tolerance)));
        EXPECT_LE(static_cast<int>(o.points.size()), bound) << "guess " << guess;
        EXPECT_TRUE(o.last.outOfOrder.empty());
    }
}

TEST(Bisection, WallThicknessHoldsAsItGrows) {
    SearchSettings s;
    s.direction = Direction::HoldsAsItGrows;
    s.guess = 4.78;
    s.tolerance = 0.1;
    s.lowest = 0.5;
    s.highest = 30.0;
    const double threshold = 6.3; // thinner walls perforate
    const Outcome o = search(s, [&](double t) { return t < threshold; });
    ASSERT_EQ(o.last.state, SearchState::Converged);
    EXPECT_LT(*o.last.failSide, threshold);
    EXPECT_GE(*o.last.holdSide, threshold);
    EXPECT_LE(*o.last.holdSide - *o.last.failSide, s.tolerance);
    // The first step from a P at the guess goes thicker.
    ASSERT_GE(o.points.size(), 2u);
    EXPECT_GT(o.points[1].value, o.points[0].value);
}

TEST(Bisection, DependsOnlyOnThePointsNotTheirOrder) {
    const SearchSettings s = diameterSearch(3.0);
    std::vector<SearchPoint> points = {{3.0, false}, {3.75, true}, {3.375, true}, {3.1875, false}};
    const SearchStep ref = nextStep(s, points);
    std::mt19937 rng(7);
    for (int k = 0; k < 10; ++k) {
        std::shuffle(points.begin(), points.end(), rng);
        const SearchStep step = nextStep(s, points);
        EXPECT_EQ(step.state, ref.state);
        EXPECT_DOUBLE_EQ(step.next, ref.next);
    }
    EXPECT_DOUBLE_EQ(ref.next, 0.5 * (3.375 + 3.1875));
}

TEST(Bisection, ReportsHeldRunsBeyondTheFailSide) {
    const SearchSettings s = diameterSearch(3.0);
    // A P at 3.3 and an NP at 3.5: the bracket is the one below the mildest P.
    const std::vector<SearchPoint> points = {{3.0, false}, {3.3, true}, {3.5, false}};
    const SearchStep step = nextStep(s, points);
    EXPECT_EQ(step.state, SearchState::RunNext);
    EXPECT_DOUBLE_EQ(*step.failSide, 3.3);
    EXPECT_DOUBLE_EQ(*step.holdSide, 3.0);
    ASSERT_EQ(step.outOfOrder.size(), 1u);
    EXPECT_DOUBLE_EQ(step.outOfOrder[0], 3.5);
}

TEST(Bisection, StopsUnbracketedAtTheEndOfTheRange) {
    SearchSettings s = diameterSearch(3.0);
    s.highest = 5.0;
    const Outcome o = search(s, [](double) { return false; }); // nothing perforates
    EXPECT_EQ(o.last.state, SearchState::Unbracketed);
    EXPECT_DOUBLE_EQ(o.points.back().value, 5.0);
    EXPECT_FALSE(o.last.failSide.has_value());
}

TEST(Bisection, StopsAtThePointLimit) {
    SearchSettings s = diameterSearch(3.0);
    s.tolerance = 1e-9;
    s.maxPoints = 6;
    const Outcome o = search(s, [](double d) { return d >= 3.1; });
    EXPECT_EQ(o.last.state, SearchState::PointLimit);
    EXPECT_EQ(o.points.size(), 6u);
}

TEST(Bisection, RefusesSettingsOutOfRange) {
    SearchSettings s = diameterSearch(3.0);
    s.stepFactor = 1.0;
    EXPECT_THROW(nextStep(s, {}), std::invalid_argument);
    s = diameterSearch(30.0); // above highest
    EXPECT_THROW(nextStep(s, {}), std::invalid_argument);
}
