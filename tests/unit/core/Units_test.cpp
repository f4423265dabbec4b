// Unit conversions: the exact definitions they rest on.
#include "core/Units.hpp"

#include <gtest/gtest.h>

using namespace hvi::units;

TEST(Units, KsiIsPoundPerSquareInch) {
    // 1 lbf = 4.4482216152605 N, 1 in = 0.0254 m (both exact by definition).
    const double psiPa = 4.4482216152605 / (0.0254 * 0.0254);
    EXPECT_NEAR(ksiToMpa(1.0), psiPa * 1000.0 / 1.0e6, 1e-12);
    EXPECT_NEAR(mpaToKsi(ksiToMpa(40.0)), 40.0, 1e-12);
}

TEST(Units, LengthsRoundTrip) {
    EXPECT_DOUBLE_EQ(mmToCm(50.8), 5.08);
    EXPECT_DOUBLE_EQ(inchToMm(2.0), 50.8);
    EXPECT_DOUBLE_EQ(cmToMm(mmToCm(3.6)), 3.6);
}
