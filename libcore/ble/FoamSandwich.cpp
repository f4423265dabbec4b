// Ryan et al. foam sandwich BLE; see FoamSandwich.hpp for source, units and ambiguities.
#include "ble/FoamSandwich.hpp"

#include "ble/ArgumentChecks.hpp"

#include <cmath>
#include <string>

namespace hvi::ble {

namespace {

// FOAM10: "apply a 5 % reduction of the hypervelocity d_c for 10 and 20 PPI".
constexpr double kCoarseFoamFactor = 0.95;
// FOAM10 sec. 3: the tests' range.
constexpr double kFoamTestedMaxAngleDeg = 60.0;
constexpr double kFoamTestedMinVelocityKmS = 2.1;
constexpr double kFoamTestedMaxVelocityKmS = 7.56;
constexpr double kFoamTestedMinCoreCm = 1.27;
constexpr double kFoamTestedMaxCoreCm = 5.08;

struct FoamTerms {
    const FoamSandwichPanel& panel;
    const FoamSandwichOptions& options;
    double rhoP;
    double c;
    double hvFactor; // PPI reduction

    double low(double v) const {
        const double x = panel.frontFacesheetCm +
                         panel.rearFacesheetCm * std::sqrt(panel.rearFacesheetYieldKsi / 40.0) +
                         std::pow(panel.coreThicknessCm, 1.1) * panel.foamDensityGCm3 /
                             panel.rearFacesheetDensityGCm3;
        const double y = std::sqrt(rhoP) * std::pow(v, 2.0 / 3.0) * std::pow(c, 0.8);
        if (options.lowVelocityExponent == FoamLowVelocityExponent::DenominatorOnly) {
            return 1.83 * x / std::pow(y, 18.0 / 19.0);
        }
        return 1.83 * std::pow(x / y, 18.0 / 19.0);
    }
    double high(double v) const {
        const double arealDensity = panel.foamDensityGCm3 * panel.coreThicknessCm;
        const double core = options.coreFactor == FoamCoreFactorReading::Multiplier
                                ? 0.89 * std::pow(panel.coreThicknessCm, 0.45)
                                : std::pow(0.89 * panel.coreThicknessCm, 0.45);
        return hvFactor * 2.152 *
               std::pow(panel.rearFacesheetCm + 0.5 * arealDensity / panel.rearFacesheetDensityGCm3,
                        2.0 / 3.0) *
               core * std::cbrt(panel.rearFacesheetYieldKsi / 70.0) /
               (std::cbrt(rhoP) * std::pow(panel.frontFacesheetDensityGCm3, 1.0 / 9.0) *
                std::pow(v, 0.4) * std::pow(c, 0.8));
    }
};

std::string readingName(const FoamSandwichOptions& o) {
    std::string text = "FOAM10 read as: ";
    text += o.lowVelocityExponent == FoamLowVelocityExponent::DenominatorOnly
                ? "18/19 on the denominator only (pyBLOSSUM)"
                : "18/19 on the whole fraction";
    text += ", ";
    text += o.coreFactor == FoamCoreFactorReading::Multiplier ? "0.89*t_f^0.45 (pyBLOSSUM)"
                                                              : "(0.89*t_f)^0.45";
    text += "; unverified against NASA/TM-2015-218593";
    return text;
}

} // namespace

double foamLowVelocityLimitKmS(double angleDeg) {
    detail::requireAngle(angleDeg);
    return 2.25 / std::cbrt(detail::cosDeg(angleDeg));
}

double foamHighVelocityLimitKmS(double angleDeg) {
    detail::requireAngle(angleDeg);
    return 4.0 / std::cbrt(detail::cosDeg(angleDeg));
}

CriticalDiameterResult foamSandwichCriticalDiameter(const FoamSandwichPanel& panel,
                                                    const Threat& threat,
                                                    const FoamSandwichOptions& options) {
    detail::requireNonNegative("front facesheet [cm]", panel.frontFacesheetCm);
    detail::requirePositive("front facesheet density [g/cm^3]", panel.frontFacesheetDensityGCm3);
    detail::requirePositive("rear facesheet [cm]", panel.rearFacesheetCm);
    detail::requirePositive("rear facesheet density [g/cm^3]", panel.rearFacesheetDensityGCm3);
    detail::requirePositive("rear facesheet yield [ksi]", panel.rearFacesheetYieldKsi);
    detail::requirePositive("core thickness [cm]", panel.coreThicknessCm);
    detail::requireNonNegative("foam density [g/cm^3]", panel.foamDensityGCm3);
    detail::requirePositive("pores per inch", panel.poresPerInch);
    detail::requirePositive("projectile density [g/cm^3]", threat.densityGCm3);
    detail::requirePositive("velocity [km/s]", threat.velocityKmS);
    detail::requireAngle(threat.angleDeg);

    CriticalDiameterResult result;
    const double ppi = panel.poresPerInch;
    const bool testedPpi = ppi == 10.0 || ppi == 20.0 || ppi == 40.0;
    // Below 40 PPI take the reduction: coarser foams were the weaker ones in the tests, and a
    // smaller d_c is the conservative side for an untested PPI.
    const double hvFactor = ppi < 40.0 ? kCoarseFoamFactor : 1.0;
    if (!testedPpi) {
        result.warnings.push_back(
            {"foam_ppi_not_tested",
             std::to_string(ppi) + " PPI: FOAM10 covers 10, 20 (5 % reduction) and 40 PPI; " +
                 (hvFactor < 1.0 ? "reduction applied" : "no reduction applied")});
    }

    const double c = detail::cosDeg(threat.angleDeg);
    const FoamTerms terms{panel, options, threat.densityGCm3, c, hvFactor};
    const double v = threat.velocityKmS;
    const double vLow = foamLowVelocityLimitKmS(threat.angleDeg);
    const double vHigh = foamHighVelocityLimitKmS(threat.angleDeg);
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
    if (options.lowVelocityExponent != FoamSandwichOptions{}.lowVelocityExponent ||
        options.coreFactor != FoamSandwichOptions{}.coreFactor) {
        result.warnings.push_back({"foam_ble_reading_b", readingName(options) +
                                                             " (not the source's reading: for "
                                                             "sensitivity studies only)"});
    }
    const double cmCore = panel.coreThicknessCm;
    std::string outside;
    if (threat.angleDeg > kFoamTestedMaxAngleDeg) {
        outside += " angle above 60 deg;";
    }
    if (v < kFoamTestedMinVelocityKmS || v > kFoamTestedMaxVelocityKmS) {
        outside += " speed outside 2.1-7.56 km/s;";
    }
    if (cmCore < kFoamTestedMinCoreCm || cmCore > kFoamTestedMaxCoreCm) {
        outside += " core outside 1.27-5.08 cm;";
    }
    if (!outside.empty()) {
        outside.pop_back();
        result.warnings.push_back(
            {"foam_outside_tested_range", "outside FOAM10's tests:" + outside});
    }
    return result;
}

} // namespace hvi::ble
