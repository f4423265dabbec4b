// Stuffed Whipple (HB09 4-45..4-50): hand values, K_H by stuffing fraction, continuity at
// the regime bounds, the printed K_Li/K_Hi intermediate form as an oracle, and the design
// equations (hand values, and design -> performance round trip).
#include "Tolerance.hpp"
#include "ble/StuffedWhipple.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi::ble;
using hvi::test::near;

namespace {
constexpr double kPi = 3.14159265358979323846;
// 1 mm Al bumper (0.27 g/cm^2), 0.3 g/cm^2 Nextel+Kevlar, 2 mm Al rear wall (0.54 g/cm^2),
// S = 11.4 cm, 40 ksi. Stuffing fraction 0.3 / 1.11 = 27 %: K_H = 0.6.
StuffedWhippleShield shield() {
    StuffedWhippleShield s;
    s.bumperCm = 0.1;
    s.stuffingArealDensityGCm2 = 0.3;
    s.rearWallCm = 0.2;
    s.standoffCm = 11.4;
    return s;
}
Threat threatAt(double v, double angleDeg = 0.0) {
    return {0.0, 2.7, v, angleDeg};
}
} // namespace

TEST(StuffedWhipple, HandValues) {
    // HV, 7 km/s normal: 0.6 * 0.54^(1/3) * 2.7^(-1/3) * 7^(-1/3) * 11.4^(2/3) * 1
    // = 0.6 * 0.8143253 * 0.7181449 * 0.5227580 * 5.0652774 = 0.9291057 cm.
    auto r = stuffedWhippleCriticalDiameter(shield(), threatAt(7.0));
    EXPECT_EQ(r.regime, Regime::Hypervelocity);
    EXPECT_TRUE(near("SW HV", r.criticalDiameterCm, 0.9291057, 0.0, 1e-6)); // 7-digit hand
    EXPECT_TRUE(r.warnings.empty());
    // LV, 2 km/s: 2.35 * 2^(-2/3) * 2.7^(-1/2) * (0.2 + 0.37 * (0.27 + 0.3))
    // = 2.35 * 0.6299605 * 0.6085806 * 0.4109 = 0.3701992 cm.
    r = stuffedWhippleCriticalDiameter(shield(), threatAt(2.0));
    EXPECT_EQ(r.regime, Regime::Ballistic);
    EXPECT_TRUE(near("SW LV", r.criticalDiameterCm, 0.3701992, 0.0, 1e-6));
    // MLI counts in the ballistic bumper areal density: +0.03 g/cm^2 -> +0.37*0.03 in brackets.
    StuffedWhippleShield withMli = shield();
    withMli.mliArealDensityGCm2 = 0.03;
    EXPECT_TRUE(near("SW LV with MLI",
                     stuffedWhippleCriticalDiameter(withMli, threatAt(2.0)).criticalDiameterCm,
                     0.3701992 * (0.4109 + 0.37 * 0.03) / 0.4109, 0.0, 1e-6));
}

TEST(StuffedWhipple, HighVelocityCoefficientByStuffingFraction) {
    // Fraction = stuffing / (bumper + stuffing + MLI + rear wall) areal density; 0.81 g/cm^2
    // of plates.
    const auto kh = [](double stuffing, bool expectWarning) {
        StuffedWhippleShield s = shield();
        s.stuffingArealDensityGCm2 = stuffing;
        std::vector<ValidityWarning> w;
        const double value = stuffedWhippleHighVelocityCoefficient(s, &w);
        EXPECT_EQ(hasWarning(w, "stuffing_fraction_outside_calibrated_range"), expectWarning)
            << "stuffing " << stuffing;
        return value;
    };
    EXPECT_DOUBLE_EQ(kh(0.11, false), 0.45); // 12 %
    EXPECT_DOUBLE_EQ(kh(0.35, false), 0.6);  // 30 %
    EXPECT_DOUBLE_EQ(kh(0.04, true), 0.45);  // 4.7 %, below both bands
    EXPECT_DOUBLE_EQ(kh(0.17, true), 0.45);  // 17 %, nearer the 10-15 % band
    EXPECT_DOUBLE_EQ(kh(0.25, true), 0.6);   // 23.6 %, nearer the 25-35 % band
    EXPECT_DOUBLE_EQ(kh(0.6, true), 0.6);    // 42.6 %
    // A caller-imposed K_H wins and scales the HV branch linearly.
    StuffedWhippleShield imposed = shield();
    imposed.highVelocityCoefficient = 0.45;
    EXPECT_TRUE(near("imposed K_H",
                     stuffedWhippleCriticalDiameter(imposed, threatAt(7.0)).criticalDiameterCm,
                     0.9291057 * 0.45 / 0.6, 0.0, 1e-6));
}

TEST(StuffedWhipple, ContinuousAtRegimeBounds) {
    // Bounds V_LV = 2.6 cos^-0.5 and V_HV = 6.5 cos^-0.75 (HB09 4-47/4-48); 1e-9 as elsewhere.
    for (double angle : {0.0, 30.0, 70.0}) {
        const double c = std::cos(angle * kPi / 180.0);
        // Also at V_n = 3 and 7 km/s, the Whipple bounds, which must not be regime bounds here.
        for (double vb : {2.6 / std::sqrt(c), 6.5 / std::pow(c, 0.75), 3.0 / c, 7.0 / c}) {
            const double left =
                stuffedWhippleCriticalDiameter(shield(), threatAt(vb * (1 - 1e-12), angle))
                    .criticalDiameterCm;
            const double right =
                stuffedWhippleCriticalDiameter(shield(), threatAt(vb * (1 + 1e-12), angle))
                    .criticalDiameterCm;
            EXPECT_TRUE(near("SW continuity", left, right, 0.0, 1e-9));
        }
    }
}

TEST(StuffedWhipple, IntermediateMatchesPrintedKliKhiForm) {
    // Oracle: HB09 4-50 written with its printed constants K_Li = 1.243, K_Hi = 0.321:
    //   d_c = K_Li (t_w (s/40)^0.5 + 0.37 m_b) cos^-1 rho_p^-0.5 (V_HV - V)/(V_HV - V_LV)
    //       + K_Hi (t_w rho_w)^(1/3) rho_p^(-1/3) S^(2/3) (s/40)^(1/6) cos^-0.25 (V - V_LV)/(...)
    // 2e-3 relative: 1.243 vs 2.35*2.6^(-2/3) = 1.24304 and 0.321 vs 0.6*6.5^(-1/3) = 0.32150.
    for (double angle : {0.0, 40.0}) {
        const double c = std::cos(angle * kPi / 180.0);
        const double vLow = 2.6 / std::sqrt(c);
        const double vHigh = 6.5 / std::pow(c, 0.75);
        const double v = 0.4 * vLow + 0.6 * vHigh;
        const double printed =
            1.243 * (0.2 + 0.37 * 0.57) / c / std::sqrt(2.7) * (vHigh - v) / (vHigh - vLow) +
            0.321 * std::cbrt(0.54) / std::cbrt(2.7) * std::pow(11.4, 2.0 / 3.0) *
                std::pow(c, -0.25) * (v - vLow) / (vHigh - vLow);
        const auto r = stuffedWhippleCriticalDiameter(shield(), threatAt(v, angle));
        EXPECT_EQ(r.regime, Regime::Shatter);
        EXPECT_TRUE(near("HB09 4-50", r.criticalDiameterCm, printed, 0.0, 2e-3));
    }
}

TEST(StuffedWhipple, DesignHandValues) {
    // d = 0.5 cm Al at 7 km/s, S = 11.4 cm, all Al, 40 ksi:
    // t_b = 0.15 * 0.5 * 2.7 / 2.7 = 0.075 cm; m_NK = 0.23 * 1.35 = 0.3105 g/cm^2
    // (Nextel 0.232875, Kevlar 0.077625); the bracket is 0.38 d rho_p / (0.2025 + 0.3105) = 1,
    // t_w = 8.84 * M_p * 7 / (2.7 * 11.4^2), M_p = pi/6 * 0.125 * 2.7 = 0.1767146 g
    //     = 0.03116372 cm.
    const Threat threat{0.5, 2.7, 7.0, 0.0};
    const auto d = designStuffedWhipple(threat, {2.7, 2.7, 40.0, 11.4});
    EXPECT_TRUE(near("t_b", d.bumperCm, 0.075, 0.0, 1e-12));
    EXPECT_TRUE(near("m_NK", d.stuffingArealDensityGCm2, 0.3105, 0.0, 1e-12));
    EXPECT_TRUE(near("Nextel", d.nextelArealDensityGCm2, 0.232875, 0.0, 1e-12));
    EXPECT_TRUE(near("Kevlar", d.kevlarArealDensityGCm2, 0.077625, 0.0, 1e-12));
    EXPECT_TRUE(near("t_w", d.rearWallCm, 0.03116372, 0.0, 1e-6));
    EXPECT_TRUE(d.warnings.empty());
    // A bumper+stuffing half as heavy needs 2^1.1 times the rear wall.
    EXPECT_TRUE(
        near("lighter bumper",
             stuffedWhippleRearWallCm(threat, 0.5 * 0.2025, 0.5 * 0.3105, {2.7, 2.7, 40.0, 11.4}),
             d.rearWallCm * std::pow(2.0, 1.1), 0.0, 1e-12));
    // Below the hypervelocity branch the design equations are extrapolated.
    EXPECT_TRUE(
        hasWarning(designStuffedWhipple({0.5, 2.7, 6.0, 0.0}, {2.7, 2.7, 40.0, 11.4}).warnings,
                   "design_below_hypervelocity_regime"));
}

TEST(StuffedWhipple, DesignRoundTripsThroughPerformance) {
    // Substituting the design t_w into the HV performance equation with K_H = 0.6 gives
    // d_c = 0.6 * 8.84^(1/3) * (pi/6)^(1/3) d = 0.99990 d: HB09's c_w = 8.84 is the
    // inversion constant (BLAP09's 8.8 would give 0.99839 d). 2e-4 covers the rounding.
    for (double angle : {0.0, 45.0}) {
        const Threat threat{0.5, 2.7, 10.0, angle};
        const StuffedWhippleDesignInput in{2.7, 2.7, 50.0, 11.4};
        const auto d = designStuffedWhipple(threat, in);
        StuffedWhippleShield s;
        s.bumperCm = d.bumperCm;
        s.stuffingArealDensityGCm2 = d.stuffingArealDensityGCm2;
        s.rearWallCm = d.rearWallCm;
        s.rearWallYieldKsi = 50.0;
        s.standoffCm = 11.4;
        s.highVelocityCoefficient = 0.6;
        const auto r = stuffedWhippleCriticalDiameter(s, threat);
        ASSERT_EQ(r.regime, Regime::Hypervelocity);
        EXPECT_TRUE(near("design round trip", r.criticalDiameterCm, 0.5, 0.0, 2e-4));
    }
}
