// Honeycomb-core sandwich panels: the SRL (Schaefer-Ryan-Lambert) ballistic limit equation
// in its double-wall form, its facesheet sizing form, and the handbook rough rule.
//
// Sources:
//  - SRL: S. Ryan, F. Schaefer, R. Destefanis, M. Lambert, Adv. Space Res. 41 (2008)
//    1152-1166, doi:10.1016/j.asr.2007.02.032; F. Schaefer et al., IJIE 35 (2008) 1784-1791;
//    S. Ryan, E.L. Christiansen, NASA/TM-2009-214789 (BLAP09) eqs 56-60 and Tables 11-12;
//    Acta Astronautica 69 (2011) 245-257.
//  - Rough rule: NASA/TM-2009-214785 (HB09) section 6.1, eq 6-1: the Whipple NNO equation
//    with the standoff limited to S = min(2 D_cell, t_core), because the cell walls channel
//    the debris cloud and stop it spreading beyond about two cells.
//
// Units: cm, g/cm^3, km/s, ksi, angle in degrees from the normal. t_b is the front facesheet,
// t_w the rear facesheet, S the core thickness.
//
//   V_n <= V_LV: d_c = [(t_w/K3S (s/40)^0.5 + t_b) / (0.6 cos^delta rho_p^0.5 V^(2/3))]^(18/19)
//   V_n >= V_HV: d_c = 1.155 S^(1/3) t_w^(2/3) (s/70)^(1/3)
//                      / (K3D^(2/3) rho_p^(1/3) rho_b^(1/9) V^(2/3) cos^delta)
//   between:     linear interpolation in V between V_LV/cos and V_HV/cos.
//   Al facesheets (BLAP09 Table 11): V_LV = 3, V_HV = 7, K3S = 1.4, K3D = 0.4;
//   delta = 4/3 for theta <= 45 or theta >= 65 deg, 5/4 for 45 < theta < 65 deg.
//   Sizing (BLAP09 eq 57, t_b = t_w = t): the exact inversion of the hypervelocity branch,
//   t = 1.155^(-3/2) d^(3/2) K3D rho_p^(1/2) rho_b^(1/6) S^(-1/2) V cos^(3 delta/2) (70/s)^(1/2).
//
// Known misprints / caveats:
//  - BLAP09 prints 0.8056 for 1.155^(-3/2) = 0.805614; we use the exact value so sizing and
//    performance invert each other exactly.
//  - The delta rule makes d_c jump at 45 and 65 deg: that is the published equation.
//  - With K3S = 1, K3D = 0.16, delta = 5/3 the equation is said to reduce to the JSC
//    Whipple equation (1.155/0.16^(2/3) = 3.919 vs 3.918). That holds at normal incidence
//    and in the ballistic branch at any angle; in the hypervelocity branch SRL has
//    V^(-2/3) cos^(-5/3) where NNO has (V cos)^(-2/3), so they differ at oblique incidence.
//  - Non-Al (CFRP) facesheets need Al-equivalent thicknesses and other constants; only the
//    Al parameter set is provided here.
//  - Validated (BLAP09 Table 12) for 2-8 km/s, 0/45/60 deg, d = 0.08-0.5 cm.
#pragma once

#include "ble/Types.hpp"
#include "ble/WhippleNno.hpp"

#include <optional>

namespace hvi::ble {

/// A honeycomb-core sandwich panel (bare: no MLI, no equipment wall behind it).
struct HoneycombSandwichPanel {
    double frontFacesheetCm = 0.0;          ///< t_b [cm]
    double frontFacesheetDensityGCm3 = 2.7; ///< rho_b [g/cm^3]
    double rearFacesheetCm = 0.0;           ///< t_w [cm]
    double rearFacesheetYieldKsi = 40.0;    ///< sigma [ksi]
    double coreThicknessCm = 0.0;           ///< S [cm]
    double cellSizeCm = 0.0;                ///< D_cell [cm], used by the HB09 rough rule only
};

/// Constants of the SRL equation. Regime bounds are in normal velocity V cos(theta).
struct SrlParameters {
    double lowNormalVelocityKmS = 3.0;  ///< V_LV
    double highNormalVelocityKmS = 7.0; ///< V_HV
    double k3s = 1.4;                   ///< ballistic-regime rear-wall factor K3S
    double k3d = 0.4;                   ///< hypervelocity-regime factor K3D
    std::optional<double> delta;        ///< obliquity exponent; empty = BLAP09 rule

    /// BLAP09 Table 11, aluminium outer facesheet (the defaults above).
    static SrlParameters aluminiumFacesheets() { return {}; }
};

/// BLAP09 delta rule: 4/3 for angle <= 45 or >= 65 deg, else 5/4.
double srlObliquityExponent(double angleDeg);

/// SRL double-wall critical diameter [cm] with regime and warnings
/// (velocity_outside_validated_range 2-8 km/s, angle_outside_validated_range > 60 deg,
/// diameter_outside_validated_range 0.08-0.5 cm using threat.diameterCm when > 0, else d_c).
CriticalDiameterResult srlCriticalDiameter(const HoneycombSandwichPanel& panel,
                                           const Threat& threat,
                                           const SrlParameters& params = SrlParameters{});

/// BLAP09 eq 57: facesheet thickness t (= t_b = t_w) [cm] of an SRL panel that just stops the
/// threat in the hypervelocity regime.
double srlFacesheetDesignCm(const Threat& threat, double facesheetDensityGCm3,
                            double rearFacesheetYieldKsi, double coreThicknessCm,
                            const SrlParameters& params = SrlParameters{});

/// HB09 6-1: the Whipple shield the rough rule treats the panel as (S = min(2 D_cell, t_core)).
WhippleShield honeycombEquivalentWhipple(const HoneycombSandwichPanel& panel);

/// HB09 6-1: NNO Whipple critical diameter of honeycombEquivalentWhipple(panel).
CriticalDiameterResult honeycombHandbookCriticalDiameter(const HoneycombSandwichPanel& panel,
                                                         const Threat& threat);

} // namespace hvi::ble
