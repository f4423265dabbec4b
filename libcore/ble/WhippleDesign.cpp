// Whipple design equations; see WhippleDesign.hpp for source, units and conventions.
#include "ble/WhippleDesign.hpp"

#include "ble/ArgumentChecks.hpp"
#include "core/Units.hpp"

#include <cmath>
#include <string>

namespace hvi::ble {

namespace {
// c_w of HB09 4-22 [cm^2 s / (g^(2/3) km)].
constexpr double kRearWallCoefficient = 0.16;

void checkThreat(const Threat& threat) {
    detail::requirePositive("projectile diameter [cm]", threat.diameterCm);
    detail::requirePositive("projectile density [g/cm^3]", threat.densityGCm3);
    detail::requirePositive("velocity [km/s]", threat.velocityKmS);
    detail::requireAngle(threat.angleDeg);
}
} // namespace

double whippleBumperCoefficient(double standoffCm, double diameterCm) {
    detail::requirePositive("standoff [cm]", standoffCm);
    detail::requirePositive("projectile diameter [cm]", diameterCm);
    // C93 raised c_b from 0.20 to 0.25 at small standoffs, where a thin bumper left the rear
    // wall under-designed.
    return standoffCm / diameterCm < 30.0 ? 0.25 : 0.20;
}

double sphereMassG(double diameterCm, double densityGCm3) {
    return units::kPi * diameterCm * diameterCm * diameterCm * densityGCm3 / 6.0;
}

double whippleDesignBumperCm(const Threat& threat, double bumperDensityGCm3, double standoffCm) {
    checkThreat(threat);
    detail::requirePositive("bumper density [g/cm^3]", bumperDensityGCm3);
    const double cb = whippleBumperCoefficient(standoffCm, threat.diameterCm);
    return cb * threat.diameterCm * threat.densityGCm3 / bumperDensityGCm3;
}

double whippleDesignRearWallCm(const Threat& threat, double bumperDensityGCm3,
                               double rearWallYieldKsi, double standoffCm,
                               YieldRatioConvention convention) {
    checkThreat(threat);
    detail::requirePositive("bumper density [g/cm^3]", bumperDensityGCm3);
    detail::requirePositive("rear-wall yield [ksi]", rearWallYieldKsi);
    detail::requirePositive("standoff [cm]", standoffCm);
    const double d = threat.diameterCm;
    const double massG = sphereMassG(d, threat.densityGCm3);
    const double vn = threat.velocityKmS * detail::cosDeg(threat.angleDeg);
    const double yieldRatio = convention == YieldRatioConvention::Handbook
                                  ? std::sqrt(70.0 / rearWallYieldKsi)
                                  : std::sqrt(rearWallYieldKsi / 70.0);
    return kRearWallCoefficient * std::sqrt(d) *
           std::pow(threat.densityGCm3 * bumperDensityGCm3, 1.0 / 6.0) * std::cbrt(massG) * vn /
           std::sqrt(standoffCm) * yieldRatio;
}

WhippleDesign designWhipple(const Threat& threat, const WhippleDesignInput& input,
                            YieldRatioConvention convention) {
    WhippleDesign design;
    design.bumperCm = whippleDesignBumperCm(threat, input.bumperDensityGCm3, input.standoffCm);
    design.rearWallCm = whippleDesignRearWallCm(
        threat, input.bumperDensityGCm3, input.rearWallYieldKsi, input.standoffCm, convention);
    design.bumperCoefficient = whippleBumperCoefficient(input.standoffCm, threat.diameterCm);
    const double vn = threat.velocityKmS * detail::cosDeg(threat.angleDeg);
    if (vn < 7.0) {
        design.warnings.push_back(
            {"design_below_7km_s", "normal velocity " + std::to_string(vn) +
                                       " km/s < 7 km/s: HB09 4-21/4-22 assume V_n >= 7 km/s"});
    }
    const double sOverD = input.standoffCm / threat.diameterCm;
    if (sOverD < 15.0) {
        design.warnings.push_back(
            {"standoff_over_diameter_below_15",
             "S/d = " + std::to_string(sOverD) +
                 " < 15: the design equation may under-predict the rear wall (C93)"});
    }
    if (convention == YieldRatioConvention::ThesisInverted) {
        design.warnings.push_back(
            {"thesis_inverted_yield_ratio",
             "rear wall sized with (sigma/70)^0.5 instead of HB09's (70/sigma)^0.5 to reproduce "
             "the thesis' Table V; not a valid design"});
    }
    return design;
}

} // namespace hvi::ble
