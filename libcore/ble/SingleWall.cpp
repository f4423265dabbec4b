// Cour-Palais single-wall equations; see SingleWall.hpp for source, units and misprints.
#include "ble/SingleWall.hpp"

#include "ble/ArgumentChecks.hpp"

#include <cmath>
#include <string>

namespace hvi::ble {

namespace {

constexpr double kCourPalais = 5.24;

// Density-ratio exponent: dense projectiles penetrate relatively deeper (HB09 4-2).
double densityExponent(double rhoP, double rhoT) {
    return rhoP / rhoT < 1.5 ? 0.5 : 2.0 / 3.0;
}

void checkTarget(const SingleWallTarget& t) {
    detail::requirePositive("target density [g/cm^3]", t.densityGCm3);
    detail::requirePositive("target Brinell hardness", t.brinellHardness);
    detail::requirePositive("target sound speed [km/s]", t.soundSpeedKmS);
}

void checkThreatNoDiameter(const Threat& threat) {
    detail::requirePositive("projectile density [g/cm^3]", threat.densityGCm3);
    detail::requirePositive("velocity [km/s]", threat.velocityKmS);
    detail::requireAngle(threat.angleDeg);
}

} // namespace

double singleWallThicknessFactor(SingleWallFailure failure) {
    switch (failure) {
    case SingleWallFailure::Perforation:
        return 1.8;
    case SingleWallFailure::DetachedSpall:
        return 2.2;
    case SingleWallFailure::IncipientSpall:
        return 3.0;
    }
    return 2.2;
}

double semiInfinitePenetrationCm(const Threat& threat, const SingleWallTarget& target) {
    checkTarget(target);
    checkThreatNoDiameter(threat);
    detail::requirePositive("projectile diameter [cm]", threat.diameterCm);
    const double rhoP = threat.densityGCm3;
    const double rhoT = target.densityGCm3;
    const double vn = threat.velocityKmS * detail::cosDeg(threat.angleDeg);
    return kCourPalais * std::pow(threat.diameterCm, 19.0 / 18.0) *
           std::pow(target.brinellHardness, -0.25) *
           std::pow(rhoP / rhoT, densityExponent(rhoP, rhoT)) *
           std::pow(vn / target.soundSpeedKmS, 2.0 / 3.0);
}

double singleWallRequiredThicknessCm(const Threat& threat, const SingleWallTarget& target,
                                     SingleWallFailure failure) {
    return singleWallThicknessFactor(failure) * semiInfinitePenetrationCm(threat, target);
}

CriticalDiameterResult singleWallCriticalDiameter(const SingleWallTarget& target,
                                                  const Threat& threat, SingleWallFailure failure) {
    checkTarget(target);
    checkThreatNoDiameter(threat);
    detail::requirePositive("target thickness [cm]", target.thicknessCm);
    const double rhoP = threat.densityGCm3;
    const double rhoT = target.densityGCm3;
    const double vn = threat.velocityKmS * detail::cosDeg(threat.angleDeg);
    const double k = singleWallThicknessFactor(failure);

    CriticalDiameterResult result;
    result.regime = Regime::Ballistic;
    result.criticalDiameterCm =
        std::pow(target.thicknessCm * std::pow(target.brinellHardness, 0.25) *
                     std::pow(rhoT / rhoP, densityExponent(rhoP, rhoT)) /
                     (k * kCourPalais * std::pow(vn / target.soundSpeedKmS, 2.0 / 3.0)),
                 18.0 / 19.0);
    if (threat.velocityKmS > 8.0) {
        result.warnings.push_back({"velocity_outside_validated_range",
                                   "velocity " + std::to_string(threat.velocityKmS) +
                                       " km/s > 8 km/s, the single-wall validation limit (HB09)"});
    }
    if (threat.angleDeg > 85.0) {
        result.warnings.push_back({"angle_outside_validated_range",
                                   "obliquity " + std::to_string(threat.angleDeg) +
                                       " deg > 85 deg, outside the validated 0-85 deg (HB09)"});
    }
    return result;
}

} // namespace hvi::ble
