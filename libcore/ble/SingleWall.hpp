// Single metallic wall (monolithic plate): Cour-Palais / JSC semi-infinite penetration depth,
// the thickness that resists a threat, and the critical diameter of a given plate.
//
// Source: NASA/TM-2009-214785 (HB09) section 4.1.1, eqs 4-1 to 4-6, after B.G. Cour-Palais,
// Int. J. Impact Eng. 5 (1987) 221-237 (HB09 cites the 1990 reprint, IJIE 10:135);
// BLAP09 (NASA/TM-2009-214789) "Metallic single wall".
//
// Units: cm, g/cm^3, km/s (also the target sound speed C_t), Brinell hardness BHN;
// angle in degrees from the normal.
//
//   P_inf = 5.24 d^(19/18) BHN^(-1/4) (rho_p/rho_t)^beta (V cos(theta) / C_t)^(2/3)
//           beta = 1/2 for rho_p/rho_t < 1.5, beta = 2/3 for rho_p/rho_t >= 1.5 (HB09 4-1/4-2)
//   t = k P_inf, k = 1.8 perforation, 2.2 detached spall, 3.0 incipient spall (HB09 4-3..4-5)
//   d_c = [t BHN^(1/4) (rho_t/rho_p)^beta / (k 5.24 (V cos(theta)/C_t)^(2/3))]^(18/19) (4-6)
//
// Known misprints / caveats:
//  - pyBLOSSUM codes beta = 3/2 for rho_p/rho_t >= 1.5; HB09 4-2 has 2/3. We follow HB09.
//  - HB09 4-6 is printed with the rho^0.5 factor only. We invert P_inf exactly, with the
//    same beta branch, so t(d_c) = t holds for dense projectiles too (identical to the
//    printed form for rho_p/rho_t < 1.5).
//  - Validated below 8 km/s and at 0-85 deg; HB09 says it slightly over-predicts
//    penetration above 45 deg. No angle cap.
#pragma once

#include "ble/Types.hpp"

namespace hvi::ble {

/// The failure the wall must resist, with its HB09 thickness factor k.
enum class SingleWallFailure {
    Perforation,    ///< k = 1.8 (HB09 4-3)
    DetachedSpall,  ///< k = 2.2 (HB09 4-4)
    IncipientSpall, ///< k = 3.0 (HB09 4-5)
};

/// The factor k of t = k P_inf.
double singleWallThicknessFactor(SingleWallFailure failure);

/// A metallic target plate.
struct SingleWallTarget {
    double thicknessCm = 0.0;    ///< t [cm] (ignored by the penetration/thickness calls)
    double densityGCm3 = 2.7;    ///< rho_t [g/cm^3]
    double brinellHardness = 95; ///< BHN (Al 6061-T6: 95, BLAP09 Table 1)
    double soundSpeedKmS = 5.05; ///< C_t [km/s] (Al 6061-T6: 5.05, BLAP09 Table 1)
};

/// HB09 4-1/4-2: semi-infinite penetration depth P_inf [cm] of the threat.
double semiInfinitePenetrationCm(const Threat& threat, const SingleWallTarget& target);

/// HB09 4-3..4-5: thickness [cm] that just resists `failure`.
double singleWallRequiredThicknessCm(const Threat& threat, const SingleWallTarget& target,
                                     SingleWallFailure failure = SingleWallFailure::DetachedSpall);

/// HB09 4-6: critical diameter [cm] of target.thicknessCm for `failure`. Regime is reported
/// as Ballistic (the equation is a single cratering law). Warnings:
/// velocity_outside_validated_range (V > 8 km/s), angle_outside_validated_range (> 85 deg).
CriticalDiameterResult
singleWallCriticalDiameter(const SingleWallTarget& target, const Threat& threat,
                           SingleWallFailure failure = SingleWallFailure::DetachedSpall);

} // namespace hvi::ble
