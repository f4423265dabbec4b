// Stuffed Whipple shield (Al bumper, Nextel/Kevlar intermediate layer, Al rear wall):
// performance and design equations.
//
// Sources: NASA/TM-2009-214785 (HB09) section 4.3, eqs 4-45 to 4-50; E.L. Christiansen,
// J.H. Kerr, Int. J. Impact Eng. 26 (2001) 93-104; BLAP09 (NASA/TM-2009-214789) and
// S. Ryan, E.L. Christiansen, Acta Astronautica 69 (2011) 245-257, eqs 68-71 (design).
//
// Units: cm, g/cm^3, km/s, ksi, areal densities in g/cm^2, M_p in g; angle in degrees.
// S is the overall spacing from the bumper to the rear wall; the stuffing sits at S/2.
//
// Performance:
//   V >= 6.5 cos^(-0.75):
//     d_c = K_H (t_w rho_w)^(1/3) rho_p^(-1/3) V^(-1/3) cos^(-0.5) S^(2/3) (s/40)^(1/6)
//     K_H = 0.6 when the stuffing is 25-35 % of the shield areal density, 0.45 for 10-15 %.
//   V <= 2.6 cos^(-0.5):
//     d_c = 2.35 V^(-2/3) cos^(-4/3) rho_p^(-0.5) [t_w (s/40)^0.5 + 0.37 m_b,total]
//     m_b,total = bumper + Nextel + Kevlar (+ MLI) areal density.
//   between: linear interpolation in V (HB09 4-50, constants K_Li = 1.243, K_Hi = 0.321/0.241
//   are the two branches at their bounds). No cut-off angle.
// Design:
//   t_b = 0.15 d rho_p / rho_b;  m_NK = 0.23 d rho_p (75 % Nextel, 25 % Kevlar);
//   t_w = c_w [0.38 d rho_p / (t_b rho_b + m_NK)]^1.1 M_p V cos^(3/2) / (rho_w S^2 (s/40)^0.5),
//   c_w = 8.84 s/km.
//
// Known misprints / caveats:
//  - BLAP09 and RC11 print c_w = 8.8; HB09 has 8.84, used here. With 8.84 and K_H = 0.6 the
//    design and the performance equation invert each other to 1e-4.
//  - HB09 gives K_H only for the two stuffing-fraction bands. Outside them we take the
//    nearer band's value (0.45 below 20 %, 0.6 from 20 %) and warn
//    (stuffing_fraction_outside_calibrated_range); the caller may impose K_H instead.
//  - The design equations describe the hypervelocity branch; below it a
//    design_below_hypervelocity_regime warning is issued.
#pragma once

#include "ble/Types.hpp"

#include <optional>
#include <vector>

namespace hvi::ble {

struct StuffedWhippleShield {
    double bumperCm = 0.0;                         ///< t_b [cm]
    double bumperDensityGCm3 = 2.7;                ///< rho_b [g/cm^3]
    double stuffingArealDensityGCm2 = 0.0;         ///< Nextel + Kevlar m_NK [g/cm^2]
    double mliArealDensityGCm2 = 0.0;              ///< MLI, added to m_b,total [g/cm^2]
    double rearWallCm = 0.0;                       ///< t_w [cm]
    double rearWallDensityGCm3 = 2.7;              ///< rho_w [g/cm^3]
    double rearWallYieldKsi = 40.0;                ///< sigma [ksi]
    double standoffCm = 0.0;                       ///< S, bumper to rear wall [cm]
    std::optional<double> highVelocityCoefficient; ///< K_H; empty = chosen from the fraction
};

/// K_H by stuffing fraction (see header notes); `warnings` receives the range warning.
double stuffedWhippleHighVelocityCoefficient(const StuffedWhippleShield& shield,
                                             std::vector<ValidityWarning>* warnings = nullptr);

/// HB09 4-45..4-50 critical diameter [cm] with regime and warnings.
CriticalDiameterResult stuffedWhippleCriticalDiameter(const StuffedWhippleShield& shield,
                                                      const Threat& threat);

struct StuffedWhippleDesignInput {
    double bumperDensityGCm3 = 2.7;   ///< rho_b [g/cm^3]
    double rearWallDensityGCm3 = 2.7; ///< rho_w [g/cm^3]
    double rearWallYieldKsi = 40.0;   ///< sigma [ksi]
    double standoffCm = 0.0;          ///< S [cm]
};

struct StuffedWhippleDesign {
    double bumperCm = 0.0;                 ///< t_b [cm]
    double stuffingArealDensityGCm2 = 0.0; ///< m_NK [g/cm^2]
    double nextelArealDensityGCm2 = 0.0;   ///< 75 % of m_NK
    double kevlarArealDensityGCm2 = 0.0;   ///< 25 % of m_NK
    double rearWallCm = 0.0;               ///< t_w [cm]
    std::vector<ValidityWarning> warnings;
};

/// HB09 rear-wall design equation for a given bumper and stuffing (areal densities, g/cm^2).
double stuffedWhippleRearWallCm(const Threat& threat, double bumperArealDensityGCm2,
                                double stuffingArealDensityGCm2,
                                const StuffedWhippleDesignInput& input);

/// HB09 design: t_b, m_NK (and its Nextel/Kevlar split), t_w.
StuffedWhippleDesign designStuffedWhipple(const Threat& threat,
                                          const StuffedWhippleDesignInput& input);

} // namespace hvi::ble
