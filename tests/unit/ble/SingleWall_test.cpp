// Cour-Palais single-wall equations (HB09 4-1..4-6): hand values for both density-ratio
// branches, the k factors, and design/performance inversion, plus the printed 4-6 oracle.
#include "Tolerance.hpp"
#include "ble/SingleWall.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi::ble;
using hvi::test::near;

namespace {
// Al 6061-T6, BLAP09 Table 1: rho 2.70, BHN 95, C 5.05 km/s.
SingleWallTarget al6061(double thicknessCm = 0.0) {
    return {thicknessCm, 2.7, 95.0, 5.05};
}
} // namespace

TEST(SingleWall, PenetrationAlOnAlHandValue) {
    // 1 mm Al sphere at 7 km/s, normal: rho_p/rho_t = 1 < 1.5, beta = 1/2:
    // 5.24 * 0.1^(19/18) * 95^(-1/4) * 1 * (7/5.05)^(2/3)
    // = 5.24 * 0.0879923 * 0.3203090 * 1.2431908 = 0.1836042 cm.
    const double p = semiInfinitePenetrationCm({0.1, 2.7, 7.0, 0.0}, al6061());
    EXPECT_TRUE(near("P_inf Al/Al", p, 0.1836042, 0.0, 1e-6)); // 7-digit hand value
}

TEST(SingleWall, PenetrationDenseProjectileUsesTwoThirds) {
    // Steel (7.8) on Al: ratio 2.889 >= 1.5, beta = 2/3 (HB09 4-2; pyBLOSSUM's 3/2 would give
    // 2.889^1.5 = 4.91 instead of 2.889^(2/3) = 2.028):
    // 5.24 * 0.0879923 * 0.3203090 * 2.0284014 * 1.2431908 = 0.3724230 cm.
    const double p = semiInfinitePenetrationCm({0.1, 7.8, 7.0, 0.0}, al6061());
    EXPECT_TRUE(near("P_inf steel/Al", p, 0.3724230, 0.0, 1e-6));
    // Just below the switch the square root applies.
    const double pLow = semiInfinitePenetrationCm({0.1, 1.49 * 2.7, 7.0, 0.0}, al6061());
    EXPECT_TRUE(near("P_inf ratio 1.49", pLow, 0.1836042 * std::sqrt(1.49), 0.0, 1e-6));
}

TEST(SingleWall, ThicknessFactors) {
    const Threat t{0.1, 2.7, 7.0, 0.0};
    const double p = semiInfinitePenetrationCm(t, al6061());
    EXPECT_TRUE(near("perforation",
                     singleWallRequiredThicknessCm(t, al6061(), SingleWallFailure::Perforation),
                     1.8 * p, 0.0, 1e-14));
    EXPECT_TRUE(near("detached spall",
                     singleWallRequiredThicknessCm(t, al6061(), SingleWallFailure::DetachedSpall),
                     2.2 * p, 0.0, 1e-14));
    EXPECT_TRUE(near("incipient spall",
                     singleWallRequiredThicknessCm(t, al6061(), SingleWallFailure::IncipientSpall),
                     3.0 * p, 0.0, 1e-14));
}

TEST(SingleWall, CriticalDiameterInvertsThickness) {
    // t(d_c(t)) = t for both density branches, every failure mode and an oblique impact.
    for (double rhoP : {2.7, 7.8}) {
        for (auto mode : {SingleWallFailure::Perforation, SingleWallFailure::DetachedSpall,
                          SingleWallFailure::IncipientSpall}) {
            const SingleWallTarget target = al6061(0.3);
            const Threat threat{0.0, rhoP, 6.0, 30.0};
            const auto r = singleWallCriticalDiameter(target, threat, mode);
            Threat atDc = threat;
            atDc.diameterCm = r.criticalDiameterCm;
            EXPECT_TRUE(near("round trip", singleWallRequiredThicknessCm(atDc, target, mode), 0.3,
                             0.0, 1e-12));
        }
    }
}

TEST(SingleWall, CriticalDiameterMatchesPrintedHb09_4_6) {
    // Oracle: HB09 4-6 as printed (rho ratio < 1.5),
    //   d_c = [t BHN^0.25 (rho_t/rho_p)^0.5 / (k 5.24 (V cos / C)^(2/3))]^(18/19),
    // 3 mm plate, 2.8 g/cm^3 projectile, 7 km/s at 45 deg, detached spall.
    const double vn = 7.0 * std::cos(3.14159265358979323846 / 4.0);
    const double printed = std::pow(0.3 * std::pow(95.0, 0.25) * std::sqrt(2.7 / 2.8) /
                                        (2.2 * 5.24 * std::pow(vn / 5.05, 2.0 / 3.0)),
                                    18.0 / 19.0);
    const auto r = singleWallCriticalDiameter(al6061(0.3), {0.0, 2.8, 7.0, 45.0});
    EXPECT_TRUE(near("HB09 4-6", r.criticalDiameterCm, printed, 0.0, 1e-12));
    EXPECT_TRUE(r.warnings.empty());
}

TEST(SingleWall, Warnings) {
    EXPECT_TRUE(hasWarning(singleWallCriticalDiameter(al6061(0.3), {0.0, 2.7, 9.0, 0.0}).warnings,
                           "velocity_outside_validated_range"));
    EXPECT_TRUE(hasWarning(singleWallCriticalDiameter(al6061(0.3), {0.0, 2.7, 7.0, 87.0}).warnings,
                           "angle_outside_validated_range"));
}
