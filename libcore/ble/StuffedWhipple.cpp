// Stuffed Whipple equations; see StuffedWhipple.hpp for sources, units and caveats.
#include "ble/StuffedWhipple.hpp"

#include "ble/ArgumentChecks.hpp"
#include "ble/WhippleDesign.hpp"

#include <cmath>
#include <string>

namespace hvi::ble {

namespace {

constexpr double kDesignBumper = 0.15;   // c_b
constexpr double kDesignStuffing = 0.23; // c_NK
constexpr double kDesignSum = 0.38;      // c_0 = c_b + c_NK
constexpr double kDesignRearWall = 8.84; // c_w [s/km], HB09
constexpr double kNextelShare = 0.75;

double lowVelocityLimitKmS(double c) {
    return 2.6 / std::sqrt(c);
}
double highVelocityLimitKmS(double c) {
    return 6.5 / std::pow(c, 0.75);
}

void checkShield(const StuffedWhippleShield& s) {
    detail::requireNonNegative("bumper [cm]", s.bumperCm);
    detail::requirePositive("bumper density [g/cm^3]", s.bumperDensityGCm3);
    detail::requireNonNegative("stuffing areal density [g/cm^2]", s.stuffingArealDensityGCm2);
    detail::requireNonNegative("MLI areal density [g/cm^2]", s.mliArealDensityGCm2);
    detail::requirePositive("rear wall [cm]", s.rearWallCm);
    detail::requirePositive("rear-wall density [g/cm^3]", s.rearWallDensityGCm3);
    detail::requirePositive("rear-wall yield [ksi]", s.rearWallYieldKsi);
    detail::requirePositive("standoff [cm]", s.standoffCm);
}

} // namespace

double stuffedWhippleHighVelocityCoefficient(const StuffedWhippleShield& shield,
                                             std::vector<ValidityWarning>* warnings) {
    if (shield.highVelocityCoefficient) {
        detail::requirePositive("K_H", *shield.highVelocityCoefficient);
        return *shield.highVelocityCoefficient;
    }
    checkShield(shield);
    const double total = shield.bumperCm * shield.bumperDensityGCm3 +
                         shield.stuffingArealDensityGCm2 + shield.mliArealDensityGCm2 +
                         shield.rearWallCm * shield.rearWallDensityGCm3;
    const double fraction = shield.stuffingArealDensityGCm2 / total;
    const bool lowBand = fraction >= 0.10 && fraction <= 0.15;
    const bool highBand = fraction >= 0.25 && fraction <= 0.35;
    if (!lowBand && !highBand && warnings != nullptr) {
        warnings->push_back({"stuffing_fraction_outside_calibrated_range",
                             "stuffing is " + std::to_string(100.0 * fraction) +
                                 " % of the shield areal density; HB09 gives K_H for 10-15 % "
                                 "(0.45) and 25-35 % (0.6) only; nearer band used"});
    }
    return fraction < 0.20 ? 0.45 : 0.6;
}

CriticalDiameterResult stuffedWhippleCriticalDiameter(const StuffedWhippleShield& shield,
                                                      const Threat& threat) {
    checkShield(shield);
    detail::requirePositive("projectile density [g/cm^3]", threat.densityGCm3);
    detail::requirePositive("velocity [km/s]", threat.velocityKmS);
    detail::requireAngle(threat.angleDeg);

    CriticalDiameterResult result;
    const double kh = stuffedWhippleHighVelocityCoefficient(shield, &result.warnings);
    const double c = detail::cosDeg(threat.angleDeg);
    const double rhoP = threat.densityGCm3;
    const double yieldRatio = shield.rearWallYieldKsi / 40.0;
    const double bumperTotal = shield.bumperCm * shield.bumperDensityGCm3 +
                               shield.stuffingArealDensityGCm2 + shield.mliArealDensityGCm2;

    const auto low = [&](double v) {
        return 2.35 * std::pow(v, -2.0 / 3.0) * std::pow(c, -4.0 / 3.0) / std::sqrt(rhoP) *
               (shield.rearWallCm * std::sqrt(yieldRatio) + 0.37 * bumperTotal);
    };
    const auto high = [&](double v) {
        return kh * std::cbrt(shield.rearWallCm * shield.rearWallDensityGCm3) / std::cbrt(rhoP) /
               std::cbrt(v) / std::sqrt(c) * std::pow(shield.standoffCm, 2.0 / 3.0) *
               std::pow(yieldRatio, 1.0 / 6.0);
    };

    const double v = threat.velocityKmS;
    const double vLow = lowVelocityLimitKmS(c);
    const double vHigh = highVelocityLimitKmS(c);
    if (v <= vLow) {
        result.regime = Regime::Ballistic;
        result.criticalDiameterCm = low(v);
    } else if (v >= vHigh) {
        result.regime = Regime::Hypervelocity;
        result.criticalDiameterCm = high(v);
    } else {
        result.regime = Regime::Shatter;
        result.criticalDiameterCm =
            low(vLow) + (high(vHigh) - low(vLow)) * (v - vLow) / (vHigh - vLow);
    }
    return result;
}

double stuffedWhippleRearWallCm(const Threat& threat, double bumperArealDensityGCm2,
                                double stuffingArealDensityGCm2,
                                const StuffedWhippleDesignInput& input) {
    detail::requirePositive("projectile diameter [cm]", threat.diameterCm);
    detail::requirePositive("projectile density [g/cm^3]", threat.densityGCm3);
    detail::requirePositive("velocity [km/s]", threat.velocityKmS);
    detail::requireAngle(threat.angleDeg);
    detail::requirePositive("bumper + stuffing areal density [g/cm^2]",
                            bumperArealDensityGCm2 + stuffingArealDensityGCm2);
    detail::requirePositive("rear-wall density [g/cm^3]", input.rearWallDensityGCm3);
    detail::requirePositive("rear-wall yield [ksi]", input.rearWallYieldKsi);
    detail::requirePositive("standoff [cm]", input.standoffCm);
    const double d = threat.diameterCm;
    const double c = detail::cosDeg(threat.angleDeg);
    // A lighter bumper+stuffing than the design's 0.38 d rho_p fragments the projectile less,
    // so the rear wall grows with the ratio to the power 1.1.
    const double shortfall =
        kDesignSum * d * threat.densityGCm3 / (bumperArealDensityGCm2 + stuffingArealDensityGCm2);
    return kDesignRearWall * std::pow(shortfall, 1.1) * sphereMassG(d, threat.densityGCm3) *
           threat.velocityKmS * std::pow(c, 1.5) /
           (input.rearWallDensityGCm3 * input.standoffCm * input.standoffCm *
            std::sqrt(input.rearWallYieldKsi / 40.0));
}

StuffedWhippleDesign designStuffedWhipple(const Threat& threat,
                                          const StuffedWhippleDesignInput& input) {
    detail::requirePositive("projectile diameter [cm]", threat.diameterCm);
    detail::requirePositive("projectile density [g/cm^3]", threat.densityGCm3);
    detail::requirePositive("bumper density [g/cm^3]", input.bumperDensityGCm3);
    StuffedWhippleDesign design;
    const double projectileAreal = threat.diameterCm * threat.densityGCm3;
    design.bumperCm = kDesignBumper * projectileAreal / input.bumperDensityGCm3;
    design.stuffingArealDensityGCm2 = kDesignStuffing * projectileAreal;
    design.nextelArealDensityGCm2 = kNextelShare * design.stuffingArealDensityGCm2;
    design.kevlarArealDensityGCm2 = (1.0 - kNextelShare) * design.stuffingArealDensityGCm2;
    design.rearWallCm = stuffedWhippleRearWallCm(threat, design.bumperCm * input.bumperDensityGCm3,
                                                 design.stuffingArealDensityGCm2, input);
    const double c = detail::cosDeg(threat.angleDeg);
    if (threat.velocityKmS < highVelocityLimitKmS(c)) {
        design.warnings.push_back(
            {"design_below_hypervelocity_regime",
             "V = " + std::to_string(threat.velocityKmS) +
                 " km/s < 6.5 cos^-0.75 = " + std::to_string(highVelocityLimitKmS(c)) +
                 " km/s: the stuffed Whipple design equations describe the hypervelocity branch"});
    }
    return design;
}

} // namespace hvi::ble
