// NASA JSC Whipple shield design (sizing) equations: bumper and rear-wall thickness that
// just stop a given threat.
//
// Source: E.L. Christiansen, Int. J. Impact Eng. 14 (1993) 145-156, eqs (7)-(8); repeated as
// NASA/TM-2009-214785 (HB09) eqs 4-21 and 4-22, section 4.2.2. Thesis eqs (27), (28).
//
// Units: cm, g/cm^3, km/s, ksi; M_p in g; angle in degrees from the normal.
//
//   t_b = c_b d rho_p / rho_b                     c_b = 0.25 for S/d < 30, 0.20 for S/d >= 30
//   t_w = c_w d^0.5 (rho_p rho_b)^(1/6) M_p^(1/3) V_n / S^0.5 (70/sigma)^0.5,  c_w = 0.16
//
// m_p = d rho_p in the bumper equation is the projectile *areal* density (g/cm^2); M_p in
// the rear-wall equation is the sphere *mass* pi d^3 rho_p / 6 in g. Check: with M_p in g,
// c_w d^0.5 M_p^(1/3) = 0.129 d^1.5 rho_p^(1/3), the same constant the exact inversion of
// the V_n >= 7 performance equation gives ((1/3.918)^1.5 = 0.129), so that reading is the
// consistent one. pyBLOSSUM's F2* routine uses pi (d/2)^3 rho_p (= pi d^3/8); not copied.
//
// The equations assume V_n >= 7 km/s (HB09); below that they are extrapolated and a
// design_below_7km_s warning is issued. C93 also notes they can under-predict t_w when
// S/d < 15 or t_b rho_b / (d rho_p) < 0.18.
//
// Thesis convention: the thesis' Table V rear-wall column is reproduced only with the yield
// ratio inverted, (sigma/70)^0.5 (equivalently the correct formula with sigma = 122.5 ksi
// for sigma = 40), see ble-equations.md section 9.3. YieldRatioConvention::ThesisInverted
// exists for that reproduction only; it gives a rear wall ~43% thinner than HB09 at 40 ksi.
#pragma once

#include "ble/Types.hpp"

#include <vector>

namespace hvi::ble {

/// Which yield-stress ratio the rear-wall design equation uses.
enum class YieldRatioConvention {
    Handbook,       ///< (70/sigma)^0.5, HB09 4-22 and C93 eq 8 (correct; the default)
    ThesisInverted, ///< (sigma/70)^0.5, reproduces the thesis' Table V only
};

/// What the designer fixes besides the threat.
struct WhippleDesignInput {
    double bumperDensityGCm3 = 2.7; ///< rho_b [g/cm^3]
    double rearWallYieldKsi = 40.0; ///< sigma [ksi]
    double standoffCm = 0.0;        ///< S [cm]
};

/// A sized Whipple shield.
struct WhippleDesign {
    double bumperCm = 0.0;          ///< t_b [cm]
    double rearWallCm = 0.0;        ///< t_w [cm]
    double bumperCoefficient = 0.0; ///< c_b used (0.25 or 0.20)
    std::vector<ValidityWarning> warnings;
};

/// c_b of HB09 4-21: 0.25 for S/d < 30, 0.20 for S/d >= 30.
double whippleBumperCoefficient(double standoffCm, double diameterCm);

/// Sphere mass pi d^3 rho / 6 [g] for d in cm and rho in g/cm^3.
double sphereMassG(double diameterCm, double densityGCm3);

/// HB09 4-21: bumper thickness t_b [cm]. Angle does not enter.
double whippleDesignBumperCm(const Threat& threat, double bumperDensityGCm3, double standoffCm);

/// HB09 4-22: rear-wall thickness t_w [cm], with V_n = V cos(theta).
double whippleDesignRearWallCm(const Threat& threat, double bumperDensityGCm3,
                               double rearWallYieldKsi, double standoffCm,
                               YieldRatioConvention convention = YieldRatioConvention::Handbook);

/// Both equations plus warnings: design_below_7km_s (V_n < 7), standoff_over_diameter_below_15.
WhippleDesign designWhipple(const Threat& threat, const WhippleDesignInput& input,
                            YieldRatioConvention convention = YieldRatioConvention::Handbook);

} // namespace hvi::ble
