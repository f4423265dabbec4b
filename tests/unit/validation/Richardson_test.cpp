// Observed order and Richardson limit (validation/Richardson.hpp) on values made from the model
// f(h) = f0 + C h^p itself, where both are known exactly, and the cases with no estimate.
#include "validation/Richardson.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi::validation;

namespace {
std::vector<double> model(const std::vector<double>& h, double f0, double c, double p) {
    std::vector<double> f;
    for (double x : h) {
        f.push_back(f0 + c * std::pow(x, p));
    }
    return f;
}
} // namespace

TEST(Richardson, RecoversOrderAndLimitOnAnUnevenLadderInAnyOrder) {
    // The ladder of make convergence (ratios 1.33, 1.5, 1.33, 1.5, 1.33), shuffled.
    const std::vector<double> h = {0.04, 0.08, 0.015, 0.06, 0.02, 0.03};
    for (double p : {0.5, 1.0, 1.7, 3.0}) {
        const auto e = richardson(h, model(h, 6.7, -20.0, p));
        ASSERT_TRUE(e.ok) << e.reason;
        // Brent to 1e-10 in p; the limit then to rounding of the values.
        EXPECT_NEAR(e.order, p, 1e-8) << p;
        EXPECT_NEAR(e.limit, 6.7, 1e-9) << p;
    }
}

TEST(Richardson, UsesOnlyTheThreeFinestSpacings) {
    // A coarse point far off the model changes nothing.
    std::vector<double> h = {0.08, 0.04, 0.02, 0.01};
    auto f = model(h, 1.0, 3.0, 2.0);
    f[0] = 1e6;
    const auto e = richardson(h, f);
    ASSERT_TRUE(e.ok) << e.reason;
    EXPECT_NEAR(e.order, 2.0, 1e-8);
    EXPECT_NEAR(e.limit, 1.0, 1e-12);
}

TEST(Richardson, NoEstimateOutsideTheAsymptoticRange) {
    const std::vector<double> h = {0.08, 0.04, 0.02};
    auto e = richardson(h, {7.0, 6.0, 6.5}); // oscillating
    EXPECT_FALSE(e.ok);
    EXPECT_NE(e.reason.find("oscillating"), std::string::npos) << e.reason;
    e = richardson(h, {7.0, 6.9, 6.7}); // the difference doubles: p < 0
    EXPECT_FALSE(e.ok);
    EXPECT_NE(e.reason.find("do not shrink"), std::string::npos) << e.reason;
    e = richardson(h, {7.0, 6.0, 6.0 - 1e-6}); // p about 20
    EXPECT_FALSE(e.ok);
    EXPECT_NE(e.reason.find("above 8"), std::string::npos) << e.reason;
    e = richardson({0.08, 0.04}, {7.0, 6.0});
    EXPECT_FALSE(e.ok);
    EXPECT_NE(e.reason.find("fewer than three"), std::string::npos) << e.reason;
    e = richardson({0.08, 0.04, 0.04}, {7.0, 6.0, 6.0});
    EXPECT_FALSE(e.ok);
    // Converged to the last digit: the value itself.
    e = richardson(h, {5.0, 5.0, 5.0});
    ASSERT_TRUE(e.ok);
    EXPECT_DOUBLE_EQ(e.limit, 5.0);
}
