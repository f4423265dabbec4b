// NNO Whipple performance equation (C93 eqs 9-12 = HB09 4-23..4-26): hand values in each
// regime, continuity at the regime bounds, the printed-constant variant, the 65 deg cap,
// an independent oracle of the hypervelocity branch, and the validity warnings.
#include "Tolerance.hpp"
#include "ble/WhippleNno.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

using namespace hvi::ble;
using hvi::test::near;

namespace {
// An Al 6061-T6 Whipple shield: 1 mm bumper, 2 mm rear wall, 10 cm standoff.
WhippleShield referenceShield() {
    return {0.1, 2.7, 0.2, 40.0, 10.0};
}
Threat threatAt(double velocityKmS, double angleDeg = 0.0, double diameterCm = 0.0) {
    return {diameterCm, 2.7, velocityKmS, angleDeg};
}
double dcAt(const WhippleShield& s, double v, double angleDeg = 0.0,
            NnoShatterConstants k = NnoShatterConstants::Continuous) {
    return whippleNnoCriticalDiameter(s, threatAt(v, angleDeg), k).criticalDiameterCm;
}
} // namespace

TEST(WhippleNno, BallisticRegimeHandValue) {
    // V = 2 km/s, normal: [(0.2*(40/40)^0.5 + 0.1) / (0.6 * 2.7^0.5 * 2^(2/3))]^(18/19)
    // = (0.3 / 1.565032)^(18/19) = 0.191691^(18/19) = 0.2091025 cm (by hand, 7 digits).
    const auto r = whippleNnoCriticalDiameter(referenceShield(), threatAt(2.0));
    EXPECT_EQ(r.regime, Regime::Ballistic);
    // 1e-6 relative: the hand value is carried to 7 significant digits.
    EXPECT_TRUE(near("d_c ballistic", r.criticalDiameterCm, 0.2091025, 0.0, 1e-6));
}

TEST(WhippleNno, HypervelocityRegimeHandValue) {
    // V = 7.5 km/s, normal: 3.918 * 0.2^(2/3) * 2.7^(-4/9) * 7.5^(-2/3) * 10^(1/3) * (40/70)^(1/3)
    // = 3.918 * 0.341995 * 0.643106 * 0.260991 * 2.154435 * 0.829827 = 0.4020811 cm.
    const auto r = whippleNnoCriticalDiameter(referenceShield(), threatAt(7.5));
    EXPECT_EQ(r.regime, Regime::Hypervelocity);
    EXPECT_TRUE(near("d_c hypervelocity", r.criticalDiameterCm, 0.4020811, 0.0, 1e-6));
}

TEST(WhippleNno, ObliqueUsesNormalVelocity) {
    // 10 km/s at 45 deg: V_n = 7.071 km/s, hypervelocity, (V cos)^(-2/3):
    // 3.918 * 0.341995 * 0.643106 * 7.0711^(-2/3) * 2.154435 * 0.829827 = 0.4181812 cm.
    const auto r = whippleNnoCriticalDiameter(referenceShield(), threatAt(10.0, 45.0));
    EXPECT_EQ(r.regime, Regime::Hypervelocity);
    EXPECT_TRUE(near("d_c at 45 deg", r.criticalDiameterCm, 0.4181812, 0.0, 1e-6));
    // The same speed at normal incidence is a different (hypervelocity) value: V_n = 10.
    EXPECT_LT(dcAt(referenceShield(), 10.0), r.criticalDiameterCm);
    // 8 km/s at 60 deg is V_n = 4: shatter, although V itself is above 7.
    EXPECT_EQ(whippleNnoCriticalDiameter(referenceShield(), threatAt(8.0, 60.0)).regime,
              Regime::Shatter);
}

TEST(WhippleNno, RegimeBoundaries) {
    EXPECT_EQ(whippleNnoRegime(2.999), Regime::Ballistic);
    EXPECT_EQ(whippleNnoRegime(3.0), Regime::Ballistic);
    EXPECT_EQ(whippleNnoRegime(3.001), Regime::Shatter);
    EXPECT_EQ(whippleNnoRegime(6.999), Regime::Shatter);
    EXPECT_EQ(whippleNnoRegime(7.0), Regime::Hypervelocity);
}

TEST(WhippleNno, ContinuousAtThreeAndSevenKmS) {
    // Left and right limits at V_n = 3 and 7, at normal and oblique incidence. The step
    // 1e-12 relative moves d_c by ~1e-12 relative (d ln d_c / d ln V is O(1)), so 1e-9 leaves
    // room for round-off but fails on any jump of the size the printed constants leave (4e-5).
    const WhippleShield s = referenceShield();
    for (double angle : {0.0, 30.0, 60.0}) {
        const double c = std::cos(angle * 3.14159265358979323846 / 180.0);
        for (double vn : {3.0, 7.0}) {
            const double v = vn / c;
            const double left = dcAt(s, v * (1.0 - 1e-12), angle);
            const double right = dcAt(s, v * (1.0 + 1e-12), angle);
            EXPECT_TRUE(
                near("continuity at V_n=" + std::to_string(vn) + ", angle " + std::to_string(angle),
                     left, right, 0.0, 1e-9));
        }
    }
}

TEST(WhippleNno, PrintedConstantsOracle) {
    // Independent re-implementation of C93 eq 10 exactly as printed (1.248, 1.071), V_n = 5:
    //   [(t_w (s/40)^0.5 + t_b) / (1.248 rho_p^0.5)]^(18/19) (1.75 - 5/4)
    //   + 1.071 t_w^(2/3) rho_p^(-1/3) rho_b^(-1/9) S^(1/3) (s/70)^(1/3) (5/4 - 0.75)
    const WhippleShield s = referenceShield();
    const double printed = std::pow(0.3 / (1.248 * std::sqrt(2.7)), 18.0 / 19.0) * 0.5 +
                           1.071 * std::pow(0.2, 2.0 / 3.0) * std::pow(2.7, -4.0 / 9.0) *
                               std::cbrt(10.0) * std::cbrt(40.0 / 70.0) * 0.5;
    // The Printed option must reproduce it to round-off.
    EXPECT_TRUE(near("printed eq 10", dcAt(s, 5.0, 0.0, NnoShatterConstants::Printed), printed, 0.0,
                     1e-12));
    // The continuous default differs from it only by the rounding of the two constants:
    // 1.248 vs 1.24805 and 1.071 vs 1.07069, i.e. at most 3e-4 relative.
    const double continuous = dcAt(s, 5.0);
    EXPECT_TRUE(near("continuous vs printed", continuous, printed, 0.0, 3e-4));
    EXPECT_NE(continuous, printed);
    // As printed the curve jumps at V_n = 7 by 1.071 / 1.07069 - 1 = 2.9e-4 relative.
    const double below = dcAt(s, 7.0 * (1.0 - 1e-12), 0.0, NnoShatterConstants::Printed);
    const double above = dcAt(s, 7.0 * (1.0 + 1e-12), 0.0, NnoShatterConstants::Printed);
    EXPECT_TRUE(near("printed jump at 7", below / above - 1.0,
                     1.071 / (3.918 * std::pow(7.0, -2.0 / 3.0)) - 1.0, 1e-9, 0.0));
}

TEST(WhippleNno, HypervelocityOracleFromInvertedDesignForm) {
    // Reference section 2 'Check': inverting the V_n >= 7 branch for the rear wall gives
    //   t_w = (d/3.918)^1.5 rho_p^0.5 rho_b^(1/6) V_n S^-0.5 (70/s)^0.5.
    // A shield with that rear wall must have d_c = d exactly (different algebraic form).
    for (double d : {0.1, 0.36, 1.0}) {
        for (double vn : {7.0, 9.0, 12.0}) {
            const double rhoP = 2.8;
            const double rhoB = 2.7;
            const double S = 5.08;
            const double sigma = 57.0;
            const double tw = std::pow(d / 3.918, 1.5) * std::sqrt(rhoP) *
                              std::pow(rhoB, 1.0 / 6.0) * vn / std::sqrt(S) *
                              std::sqrt(70.0 / sigma);
            const WhippleShield shield{0.05, rhoB, tw, sigma, S};
            const auto r = whippleNnoCriticalDiameter(shield, {d, rhoP, vn, 0.0});
            EXPECT_EQ(r.regime, Regime::Hypervelocity);
            EXPECT_TRUE(near("inverted HV form", r.criticalDiameterCm, d, 0.0, 1e-12));
        }
    }
}

TEST(WhippleNno, AngleAbove65IsCapped) {
    const WhippleShield s = referenceShield();
    const auto at65 = whippleNnoCriticalDiameter(s, threatAt(7.0, 65.0));
    const auto at80 = whippleNnoCriticalDiameter(s, threatAt(7.0, 80.0));
    EXPECT_DOUBLE_EQ(at80.criticalDiameterCm, at65.criticalDiameterCm);
    EXPECT_TRUE(hasWarning(at80.warnings, "angle_above_65deg"));
    EXPECT_FALSE(hasWarning(at65.warnings, "angle_above_65deg"));
    // Below the cap the angle matters.
    EXPECT_NE(dcAt(s, 7.0, 60.0), at65.criticalDiameterCm);
}

TEST(WhippleNno, ValidityWarnings) {
    const WhippleShield s = referenceShield(); // S = 10 cm
    // d = 0.5 cm: S/d = 20, inside; t_b rho_b/(d rho_p) = 0.2 >= 0.18; V = 7 inside 2.5-8.
    auto r = whippleNnoCriticalDiameter(s, threatAt(7.0, 0.0, 0.5));
    EXPECT_TRUE(r.warnings.empty());
    // d = 0.8 cm: S/d = 12.5 < 15 and t_b ratio 0.125 < 0.18.
    r = whippleNnoCriticalDiameter(s, threatAt(7.0, 0.0, 0.8));
    EXPECT_TRUE(hasWarning(r.warnings, "standoff_over_diameter_below_15"));
    EXPECT_TRUE(hasWarning(r.warnings, "bumper_ratio_below_0_18"));
    // The S/d caveat concerns the debris-cloud terms only, not the ballistic branch.
    r = whippleNnoCriticalDiameter(s, threatAt(2.6, 0.0, 0.8));
    EXPECT_EQ(r.regime, Regime::Ballistic);
    EXPECT_FALSE(hasWarning(r.warnings, "standoff_over_diameter_below_15"));
    // Velocity outside 2.5-8 km/s, diameter above 1.9 cm.
    EXPECT_TRUE(hasWarning(whippleNnoCriticalDiameter(s, threatAt(9.0)).warnings,
                           "velocity_outside_validated_range"));
    EXPECT_TRUE(hasWarning(whippleNnoCriticalDiameter(s, threatAt(2.0)).warnings,
                           "velocity_outside_validated_range"));
    EXPECT_TRUE(hasWarning(whippleNnoCriticalDiameter(s, threatAt(7.0, 0.0, 2.0)).warnings,
                           "diameter_outside_validated_range"));
}

TEST(WhippleNno, RejectsNonPhysicalInput) {
    WhippleShield s = referenceShield();
    s.rearWallCm = -0.1;
    EXPECT_THROW(whippleNnoCriticalDiameter(s, threatAt(7.0)), std::invalid_argument);
    EXPECT_THROW(whippleNnoCriticalDiameter(referenceShield(), threatAt(7.0, 90.0)),
                 std::invalid_argument);
    EXPECT_THROW(whippleNnoCriticalDiameter(referenceShield(), threatAt(0.0)),
                 std::invalid_argument);
}
