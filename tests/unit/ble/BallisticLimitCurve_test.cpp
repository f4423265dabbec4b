// Ballistic limit curve sampler: grid, values identical to direct calls, regime sequence
// and transitions of the Whipple curve, warning de-duplication, argument checks.
#include "Tolerance.hpp"
#include "ble/BallisticLimitCurve.hpp"
#include "ble/FoamSandwich.hpp"
#include "ble/WhippleNno.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

using namespace hvi::ble;
using hvi::test::near;

namespace {
const WhippleShield kShield{0.127, 2.7, 0.318, 40.0, 10.0};
CriticalDiameterResult whippleAt(double v) {
    return whippleNnoCriticalDiameter(kShield, {0.0, 2.7, v, 0.0});
}
} // namespace

TEST(BallisticLimitCurve, DefaultGridAndValues) {
    const auto curve = sampleBallisticLimitCurve(whippleAt);
    ASSERT_EQ(curve.points.size(), 100u);
    EXPECT_DOUBLE_EQ(curve.points.front().velocityKmS, 0.5);
    EXPECT_DOUBLE_EQ(curve.points.back().velocityKmS, 15.0);
    // Uniform spacing (15 - 0.5) / 99.
    EXPECT_TRUE(near("step", curve.points[1].velocityKmS - curve.points[0].velocityKmS, 14.5 / 99.0,
                     1e-12, 0.0));
    for (const auto& p : curve.points) {
        const auto direct = whippleAt(p.velocityKmS);
        EXPECT_DOUBLE_EQ(p.criticalDiameterCm, direct.criticalDiameterCm);
        EXPECT_EQ(p.regime, direct.regime);
    }
}

TEST(BallisticLimitCurve, WhippleRegimesInOrder) {
    // 2..8 km/s in 0.5 steps: 2, 2.5, 3 ballistic (3 inclusive); 3.5..6.5 shatter; 7..8 HV.
    const auto curve = sampleBallisticLimitCurve(whippleAt, 2.0, 8.0, 13);
    ASSERT_EQ(curve.points.size(), 13u);
    for (const auto& p : curve.points) {
        const Regime expected = p.velocityKmS <= 3.0   ? Regime::Ballistic
                                : p.velocityKmS >= 7.0 ? Regime::Hypervelocity
                                                       : Regime::Shatter;
        EXPECT_EQ(p.regime, expected) << p.velocityKmS;
    }
    EXPECT_STREQ(regimeName(curve.points.front().regime), "ballistic");
    EXPECT_STREQ(regimeName(curve.points.back().regime), "hypervelocity");
}

TEST(BallisticLimitCurve, WarningsOncePerCode) {
    // Below 2.1 km/s every point is outside FOAM10's tests; the curve keeps the warning once.
    const FoamSandwichPanel panel{0.0254, 2.7, 0.0254, 2.7, 40.0, 5.08, 0.189, 40.0};
    const auto curve = sampleBallisticLimitCurve(
        [&](double v) {
            return foamSandwichCriticalDiameter(panel, {0.0, 2.7, v, 0.0});
        },
        1.0, 2.0, 50);
    int count = 0;
    for (const auto& w : curve.warnings) {
        count += w.code == "foam_outside_tested_range" ? 1 : 0;
    }
    EXPECT_EQ(count, 1);
    // The Whipple curve over 0.5-15 km/s leaves the 2.5-8 km/s validated range.
    EXPECT_TRUE(hasWarning(sampleBallisticLimitCurve(whippleAt).warnings,
                           "velocity_outside_validated_range"));
}

TEST(BallisticLimitCurve, RejectsBadArguments) {
    EXPECT_THROW(sampleBallisticLimitCurve(whippleAt, 0.0, 15.0, 10), std::invalid_argument);
    EXPECT_THROW(sampleBallisticLimitCurve(whippleAt, 5.0, 5.0, 10), std::invalid_argument);
    EXPECT_THROW(sampleBallisticLimitCurve(whippleAt, 1.0, 5.0, 1), std::invalid_argument);
    EXPECT_THROW(sampleBallisticLimitCurve(CriticalDiameterAtVelocity{}, 1.0, 5.0, 10),
                 std::invalid_argument);
}
