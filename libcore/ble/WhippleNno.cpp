// NNO Whipple performance equation; see WhippleNno.hpp for source, units and misprints.
#include "ble/WhippleNno.hpp"

#include "ble/ArgumentChecks.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace hvi::ble {

namespace {

// Regime boundaries in normal velocity (C93 eqs 9-11).
constexpr double kLowVnKmS = 3.0;
constexpr double kHighVnKmS = 7.0;
// Above this obliquity the equation is held at its 65 deg value (C93 eq 12): tests at
// larger angles showed no further gain, so extrapolating cos(theta) would be non-conservative.
constexpr double kCapAngleDeg = 65.0;

// C93 eq 9 at velocity V and cos(theta) = c.
double lowVelocityDc(const WhippleShield& s, double rhoP, double velocityKmS, double c) {
    const double numerator = s.rearWallCm * std::sqrt(s.rearWallYieldKsi / 40.0) + s.bumperCm;
    const double denominator =
        0.6 * std::pow(c, 5.0 / 3.0) * std::sqrt(rhoP) * std::pow(velocityKmS, 2.0 / 3.0);
    return std::pow(numerator / denominator, 18.0 / 19.0);
}

// C93 eq 11 at normal velocity V_n.
double hypervelocityDc(const WhippleShield& s, double rhoP, double normalVelocityKmS) {
    return 3.918 * std::pow(s.rearWallCm, 2.0 / 3.0) * std::pow(rhoP, -1.0 / 3.0) *
           std::pow(s.bumperDensityGCm3, -1.0 / 9.0) * std::pow(normalVelocityKmS, -2.0 / 3.0) *
           std::cbrt(s.standoffCm) * std::cbrt(s.rearWallYieldKsi / 70.0);
}

} // namespace

Regime whippleNnoRegime(double normalVelocityKmS) {
    if (normalVelocityKmS <= kLowVnKmS) {
        return Regime::Ballistic;
    }
    if (normalVelocityKmS >= kHighVnKmS) {
        return Regime::Hypervelocity;
    }
    return Regime::Shatter;
}

CriticalDiameterResult whippleNnoCriticalDiameter(const WhippleShield& shield, const Threat& threat,
                                                  NnoShatterConstants constants) {
    detail::requireNonNegative("bumper thickness [cm]", shield.bumperCm);
    detail::requirePositive("bumper density [g/cm^3]", shield.bumperDensityGCm3);
    detail::requirePositive("rear-wall thickness [cm]", shield.rearWallCm);
    detail::requirePositive("rear-wall yield [ksi]", shield.rearWallYieldKsi);
    detail::requirePositive("standoff [cm]", shield.standoffCm);
    detail::requirePositive("projectile density [g/cm^3]", threat.densityGCm3);
    detail::requirePositive("velocity [km/s]", threat.velocityKmS);
    detail::requireAngle(threat.angleDeg);

    CriticalDiameterResult result;
    double angleDeg = threat.angleDeg;
    if (angleDeg > kCapAngleDeg) {
        result.warnings.push_back(
            {"angle_above_65deg", "obliquity " + std::to_string(threat.angleDeg) +
                                      " deg > 65 deg: d_c evaluated at 65 deg (C93 eq 12)"});
        angleDeg = kCapAngleDeg;
    }
    const double c = detail::cosDeg(angleDeg);
    const double v = threat.velocityKmS;
    const double vn = v * c;
    const double rhoP = threat.densityGCm3;

    result.regime = whippleNnoRegime(vn);
    switch (result.regime) {
    case Regime::Ballistic:
        result.criticalDiameterCm = lowVelocityDc(shield, rhoP, v, c);
        break;
    case Regime::Hypervelocity:
        result.criticalDiameterCm = hypervelocityDc(shield, rhoP, vn);
        break;
    case Regime::Shatter: {
        // C93 eq 10 written as what it is: the two neighbouring regimes evaluated at their
        // boundaries (V_n = 3 and 7) and blended linearly in V_n, weights (1.75 - V_n/4) and
        // (V_n/4 - 0.75).
        double dLow = lowVelocityDc(shield, rhoP, kLowVnKmS / c, c);
        double dHigh = hypervelocityDc(shield, rhoP, kHighVnKmS);
        if (constants == NnoShatterConstants::Printed) {
            // Same terms with the rounded constants of C93 eq 10 in place of the exact ones.
            dLow *= std::pow(0.6 * std::pow(kLowVnKmS, 2.0 / 3.0) / 1.248, 18.0 / 19.0);
            dHigh *= 1.071 / (3.918 * std::pow(kHighVnKmS, -2.0 / 3.0));
        }
        result.criticalDiameterCm = dLow * (1.75 - vn / 4.0) + dHigh * (vn / 4.0 - 0.75);
        break;
    }
    }

    // Validity (BLAP09 Table 10; C93 section on design limits).
    if (v < 2.5 || v > 8.0) {
        result.warnings.push_back({"velocity_outside_validated_range",
                                   "velocity " + std::to_string(v) +
                                       " km/s outside the 2.5-8 km/s the NNO Whipple BLE was "
                                       "validated on (BLAP09 Table 10)"});
    }
    const double d = threat.diameterCm > 0.0 ? threat.diameterCm : result.criticalDiameterCm;
    if (d > 1.9) {
        result.warnings.push_back({"diameter_outside_validated_range",
                                   "projectile diameter " + std::to_string(d) +
                                       " cm > 1.9 cm, the largest validated (BLAP09 Table 10)"});
    }
    if (result.regime != Regime::Ballistic) {
        if (shield.standoffCm / d < 15.0) {
            result.warnings.push_back(
                {"standoff_over_diameter_below_15",
                 "S/d = " + std::to_string(shield.standoffCm / d) +
                     " < 15: the hypervelocity term may be non-conservative (BLAP09 Table 10)"});
        }
        const double bumperRatio = shield.bumperCm * shield.bumperDensityGCm3 / (d * rhoP);
        if (bumperRatio < 0.18) {
            result.warnings.push_back(
                {"bumper_ratio_below_0_18",
                 "t_b rho_b / (d rho_p) = " + std::to_string(bumperRatio) +
                     " < 0.18: bumper too thin to fragment the projectile fully; NNO may be "
                     "non-conservative (C93)"});
        }
    }
    return result;
}

} // namespace hvi::ble
