// SRL honeycomb-sandwich BLE and HB09 rough rule; see HoneycombSandwich.hpp for sources.
#include "ble/HoneycombSandwich.hpp"

#include "ble/ArgumentChecks.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace hvi::ble {

namespace {

void checkPanel(const HoneycombSandwichPanel& p) {
    detail::requireNonNegative("front facesheet [cm]", p.frontFacesheetCm);
    detail::requirePositive("front facesheet density [g/cm^3]", p.frontFacesheetDensityGCm3);
    detail::requirePositive("rear facesheet [cm]", p.rearFacesheetCm);
    detail::requirePositive("rear facesheet yield [ksi]", p.rearFacesheetYieldKsi);
    detail::requirePositive("core thickness [cm]", p.coreThicknessCm);
}

void checkThreatNoDiameter(const Threat& threat) {
    detail::requirePositive("projectile density [g/cm^3]", threat.densityGCm3);
    detail::requirePositive("velocity [km/s]", threat.velocityKmS);
    detail::requireAngle(threat.angleDeg);
}

struct SrlTerms {
    const HoneycombSandwichPanel& panel;
    const SrlParameters& params;
    double rhoP;
    double c;     // cos(theta)
    double delta; // obliquity exponent

    double low(double v) const {
        const double numerator =
            panel.rearFacesheetCm / params.k3s * std::sqrt(panel.rearFacesheetYieldKsi / 40.0) +
            panel.frontFacesheetCm;
        const double denominator =
            0.6 * std::pow(c, delta) * std::sqrt(rhoP) * std::pow(v, 2.0 / 3.0);
        return std::pow(numerator / denominator, 18.0 / 19.0);
    }
    double high(double v) const {
        return 1.155 * std::cbrt(panel.coreThicknessCm) *
               std::pow(panel.rearFacesheetCm, 2.0 / 3.0) *
               std::cbrt(panel.rearFacesheetYieldKsi / 70.0) /
               (std::pow(params.k3d, 2.0 / 3.0) * std::cbrt(rhoP) *
                std::pow(panel.frontFacesheetDensityGCm3, 1.0 / 9.0) * std::pow(v, 2.0 / 3.0) *
                std::pow(c, delta));
    }
};

} // namespace

double srlObliquityExponent(double angleDeg) {
    detail::requireAngle(angleDeg);
    return (angleDeg <= 45.0 || angleDeg >= 65.0) ? 4.0 / 3.0 : 5.0 / 4.0;
}

CriticalDiameterResult srlCriticalDiameter(const HoneycombSandwichPanel& panel,
                                           const Threat& threat, const SrlParameters& params) {
    checkPanel(panel);
    checkThreatNoDiameter(threat);
    detail::requirePositive("SRL K3S", params.k3s);
    detail::requirePositive("SRL K3D", params.k3d);
    detail::requirePositive("SRL V_LV [km/s]", params.lowNormalVelocityKmS);
    if (!(params.highNormalVelocityKmS > params.lowNormalVelocityKmS)) {
        throw std::invalid_argument("hvi::ble: SRL V_HV must exceed V_LV");
    }

    const double c = detail::cosDeg(threat.angleDeg);
    const double delta = params.delta ? *params.delta : srlObliquityExponent(threat.angleDeg);
    const SrlTerms terms{panel, params, threat.densityGCm3, c, delta};
    const double v = threat.velocityKmS;
    const double vLow = params.lowNormalVelocityKmS / c;
    const double vHigh = params.highNormalVelocityKmS / c;

    CriticalDiameterResult result;
    if (v <= vLow) {
        result.regime = Regime::Ballistic;
        result.criticalDiameterCm = terms.low(v);
    } else if (v >= vHigh) {
        result.regime = Regime::Hypervelocity;
        result.criticalDiameterCm = terms.high(v);
    } else {
        result.regime = Regime::Shatter;
        const double dLow = terms.low(vLow);
        const double dHigh = terms.high(vHigh);
        result.criticalDiameterCm = dLow + (dHigh - dLow) * (v - vLow) / (vHigh - vLow);
    }

    // Validity: BLAP09 Table 12.
    if (v < 2.0 || v > 8.0) {
        result.warnings.push_back(
            {"velocity_outside_validated_range",
             "velocity " + std::to_string(v) + " km/s outside the 2-8 km/s SRL was validated on"});
    }
    if (threat.angleDeg > 60.0) {
        result.warnings.push_back(
            {"angle_outside_validated_range", "obliquity " + std::to_string(threat.angleDeg) +
                                                  " deg > 60 deg, the largest SRL test angle"});
    }
    const double d = threat.diameterCm > 0.0 ? threat.diameterCm : result.criticalDiameterCm;
    if (d < 0.08 || d > 0.5) {
        result.warnings.push_back({"diameter_outside_validated_range",
                                   "projectile diameter " + std::to_string(d) +
                                       " cm outside the 0.08-0.5 cm SRL was validated on"});
    }
    return result;
}

double srlFacesheetDesignCm(const Threat& threat, double facesheetDensityGCm3,
                            double rearFacesheetYieldKsi, double coreThicknessCm,
                            const SrlParameters& params) {
    detail::requirePositive("projectile diameter [cm]", threat.diameterCm);
    checkThreatNoDiameter(threat);
    detail::requirePositive("facesheet density [g/cm^3]", facesheetDensityGCm3);
    detail::requirePositive("rear facesheet yield [ksi]", rearFacesheetYieldKsi);
    detail::requirePositive("core thickness [cm]", coreThicknessCm);
    detail::requirePositive("SRL K3D", params.k3d);
    const double c = detail::cosDeg(threat.angleDeg);
    const double delta = params.delta ? *params.delta : srlObliquityExponent(threat.angleDeg);
    return std::pow(1.155, -1.5) * std::pow(threat.diameterCm, 1.5) * params.k3d *
           std::sqrt(threat.densityGCm3) * std::pow(facesheetDensityGCm3, 1.0 / 6.0) /
           std::sqrt(coreThicknessCm) * threat.velocityKmS * std::pow(c, 1.5 * delta) *
           std::sqrt(70.0 / rearFacesheetYieldKsi);
}

WhippleShield honeycombEquivalentWhipple(const HoneycombSandwichPanel& panel) {
    checkPanel(panel);
    detail::requirePositive("honeycomb cell size [cm]", panel.cellSizeCm);
    WhippleShield shield;
    shield.bumperCm = panel.frontFacesheetCm;
    shield.bumperDensityGCm3 = panel.frontFacesheetDensityGCm3;
    shield.rearWallCm = panel.rearFacesheetCm;
    shield.rearWallYieldKsi = panel.rearFacesheetYieldKsi;
    shield.standoffCm = std::min(2.0 * panel.cellSizeCm, panel.coreThicknessCm);
    return shield;
}

CriticalDiameterResult honeycombHandbookCriticalDiameter(const HoneycombSandwichPanel& panel,
                                                         const Threat& threat) {
    return whippleNnoCriticalDiameter(honeycombEquivalentWhipple(panel), threat);
}

} // namespace hvi::ble
