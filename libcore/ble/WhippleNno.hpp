// NASA JSC "new non-optimum" (NNO) Whipple shield performance equation: the critical
// projectile diameter d_c that just fails the rear wall (perforation or detached spall).
//
// Source: E.L. Christiansen, "Design and performance equations for advanced meteoroid and
// debris shields", Int. J. Impact Eng. 14 (1993) 145-156, eqs (9)-(12); repeated verbatim as
// NASA/TM-2009-214785 (MMOD protection handbook, "HB09") eqs 4-23 to 4-26. Thesis eq (3) is
// HB09 4-25. Validity: BLAP09 (NASA/TM-2009-214789) Table 10.
//
// Units: cm, g/cm^3, km/s, ksi (rear-wall yield), angle in degrees from the normal.
//
// Regimes by the normal velocity V_n = V cos(theta):
//   V_n <= 3      d_c = [(t_w (s/40)^0.5 + t_b) / (0.6 cos^(5/3) rho_p^0.5 V^(2/3))]^(18/19)
//   V_n >= 7      d_c = 3.918 t_w^(2/3) rho_p^(-1/3) rho_b^(-1/9) V_n^(-2/3) S^(1/3) (s/70)^(1/3)
//   3 < V_n < 7   linear interpolation in V_n between the two at V_n = 3 and V_n = 7.
// theta > 65 deg: d_c(theta) = d_c(65 deg) (C93 eq 12, HB09 4-26).
//
// Known misprints / caveats:
//  - The printed intermediate constants 1.248 and 1.071 are 0.6*3^(2/3) = 1.24805 and
//    3.918*7^(-2/3) = 1.07069 rounded, so as printed the curve jumps by ~4e-5 (V_n = 3) and
//    ~3e-4 (V_n = 7) relative. The default, NnoShatterConstants::Continuous, uses the exact
//    expressions (C93's weights (1.75 - V_n/4), (V_n/4 - 0.75) show the intent is a linear
//    blend; pyBLOSSUM does the same). NnoShatterConstants::Printed uses 1.248 and 1.071 as
//    printed; it is what the reference's Table V / S_initial numbers were computed with
//    (e.g. d_c = 3.322 mm printed vs 3.321 mm continuous for HITF04151, S_initial 55.46 vs
//    55.48 mm), see ble-equations.md section 9.
//  - The 18/19 exponent applies to the whole fraction (C93, HB09). The thesis typesets it
//    on the numerator only; that changes d_c by < 0.01 mm for its cases and is not followed.
//  - BLAP09 Table 10 prints "d_p/S < 15" for the non-conservative region: a typo for S/d.
//  - S is measured from the back of the bumper to the front of the rear wall (HB09).
#pragma once

#include "ble/Types.hpp"

namespace hvi::ble {

/// A two-wall (Whipple) shield. The rear-wall density does not enter the NNO equation.
struct WhippleShield {
    double bumperCm = 0.0;          ///< bumper thickness t_b [cm]
    double bumperDensityGCm3 = 2.7; ///< bumper density rho_b [g/cm^3]
    double rearWallCm = 0.0;        ///< rear-wall thickness t_w [cm]
    double rearWallYieldKsi = 40.0; ///< rear-wall yield stress sigma [ksi]
    double standoffCm = 0.0;        ///< bumper back to rear-wall front, S [cm]
};

/// Which constants the intermediate (shatter) regime uses; see the header notes.
enum class NnoShatterConstants {
    Continuous, ///< 0.6*3^(2/3) and 3.918*7^(-2/3): continuous at V_n = 3 and 7 (default)
    Printed,    ///< 1.248 and 1.071 as printed in C93 eq 10 / HB09 4-25
};

/// Regime of the NNO equation for a normal velocity V_n [km/s] (boundaries 3 and 7 km/s;
/// exactly 3 is Ballistic, exactly 7 is Hypervelocity, as in C93).
Regime whippleNnoRegime(double normalVelocityKmS);

/// Critical diameter d_c [cm] of the NNO Whipple equation, with regime and validity warnings:
/// angle_above_65deg (angle capped), velocity_outside_validated_range (V outside 2.5-8 km/s),
/// standoff_over_diameter_below_15 and bumper_ratio_below_0_18 (non-ballistic regimes only;
/// they use threat.diameterCm when > 0, else d_c), diameter_outside_validated_range
/// (d > 1.9 cm, same choice of d).
CriticalDiameterResult
whippleNnoCriticalDiameter(const WhippleShield& shield, const Threat& threat,
                           NnoShatterConstants constants = NnoShatterConstants::Continuous);

} // namespace hvi::ble
