// Brent's bracketed root finder: known roots, the no-bracket status, a root at an end point,
// a hard (flat/steep) function, and that it beats bisection on a smooth function.
#include "Tolerance.hpp"
#include "ble/RootFinding.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi::ble;
using hvi::test::near;

TEST(RootFinding, FindsKnownRoots) {
    // x^3 - 2x - 5: Wallis' classic, root 2.0945514815423265.
    const auto r = brentRoot([](double x) { return x * x * x - 2.0 * x - 5.0; }, 2.0, 3.0, 1e-14);
    ASSERT_TRUE(r.bracketed);
    ASSERT_TRUE(r.converged);
    EXPECT_TRUE(near("Wallis root", r.x, 2.0945514815423265, 1e-13, 0.0));
    // cos x = x: 0.7390851332151607 (Dottie number), bracket given reversed.
    const auto d = brentRoot([](double x) { return std::cos(x) - x; }, 1.0, 0.0, 1e-14);
    EXPECT_TRUE(near("Dottie", d.x, 0.7390851332151607, 1e-13, 0.0));
}

TEST(RootFinding, FasterThanBisectionOnSmoothFunction) {
    // Bisection from a width-1 bracket to 1e-12 takes 40 halvings; Brent needs far fewer.
    const auto r = brentRoot([](double x) { return std::exp(x) - 2.0; }, 0.0, 1.0, 1e-12);
    EXPECT_TRUE(near("ln 2", r.x, std::log(2.0), 1e-12, 0.0));
    EXPECT_LT(r.iterations, 15);
}

TEST(RootFinding, HardFunctionStillConverges) {
    // A near-step: flat for most of the bracket, which defeats pure secant steps; Brent must
    // fall back to bisection and still land on the root x = 0.3.
    const auto f = [](double x) { return std::atan(1e4 * (x - 0.3)); };
    const auto r = brentRoot(f, -5.0, 5.0, 1e-12);
    ASSERT_TRUE(r.converged);
    EXPECT_TRUE(near("step root", r.x, 0.3, 1e-11, 0.0));
}

TEST(RootFinding, ReportsMissingBracket) {
    const auto r = brentRoot([](double x) { return x * x + 1.0; }, -1.0, 1.0);
    EXPECT_FALSE(r.bracketed);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.iterations, 0);
}

TEST(RootFinding, RootAtEndPoint) {
    const auto r = brentRoot([](double x) { return x - 1.0; }, 1.0, 4.0);
    EXPECT_TRUE(r.converged);
    EXPECT_DOUBLE_EQ(r.x, 1.0);
}
