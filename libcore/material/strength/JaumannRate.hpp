// Hypoelastic deviatoric stress rate with the Jaumann (co-rotational) correction, 2D.
//
// References: L.D. Libersky, A.G. Petschek, T.C. Carney, J.R. Hipp, F.A. Allahdadi, "High
// strain Lagrangian hydrodynamics", J. Comput. Phys. 109 (1993) 67-75 (the SPH form);
// A.G. Petschek and L.D. Libersky, "Cylindrical smoothed particle hydrodynamics",
// J. Comput. Phys. 109 (1993) 76-83 (the hoop strain rate v_r / r in axisymmetry).
//
//   dS/dt = 2 G (D - tr(D)/3 I) + W S - S W
// with the velocity gradient L_ij = dv_i/dx_j, D = (L + L^T)/2, W = (L - L^T)/2.
// Sign check: a rigid rotation x(t) = Q(t) x0 has dQ/dt = W Q, and S(t) = Q S0 Q^T then
// satisfies dS/dt = W S - S W, so the rate above is zero in the co-rotating frame. (Texts that
// write "S W - W S" define W from the transposed gradient dv_j/dx_i; the unit test integrates a
// rigid rotation and compares with Q S0 Q^T, which only the right sign passes.)
//
// Axisymmetric: the hoop strain rate D_thth = v_r / r enters the trace (the caller passes it,
// regularised near the axis as it sees fit); the spin has no hoop component, so the rotation
// terms act in the (z, r) plane only, and dS_thth/dt = -(dS_zz/dt + dS_rr/dt) holds because
// both the deviatoric part and W S - S W are traceless. Planar strain: pass D_thth = 0.
//
// Units: velocity gradient and D_thth in 1/us, G and S in GPa, dS/dt in GPa/us.
#pragma once

#include "material/strength/StressDeviator.hpp"

namespace hvi::material {

/// In-plane velocity gradient L_ij = dv_i/dx_j in (z, r) (planar: x -> z, y -> r) [1/us].
struct VelocityGradient2D {
    double dvzDz = 0.0;
    double dvzDr = 0.0;
    double dvrDz = 0.0;
    double dvrDr = 0.0;
};

/// dS/dt [GPa/us] for deviator S, velocity gradient L, hoop strain rate D_thth (v_r/r in
/// axisymmetry, 0 in planar strain) and shear modulus G [GPa].
inline StressDeviator jaumannRate(const StressDeviator& s, const VelocityGradient2D& l,
                                  double hoopStrainRate, double shearModulus) noexcept {
    const double dzz = l.dvzDz;
    const double drr = l.dvrDr;
    const double drz = 0.5 * (l.dvzDr + l.dvrDz);
    const double meanRate = (dzz + drr + hoopStrainRate) / 3.0;
    // W = [[0, w], [-w, 0]] in (z, r), w = W_zr.
    const double w = 0.5 * (l.dvzDr - l.dvrDz);
    // (W S - S W) = [[2 w S_rz, w (S_rr - S_zz)], [w (S_rr - S_zz), -2 w S_rz]].
    const double twoG = 2.0 * shearModulus;
    return {twoG * (dzz - meanRate) + 2.0 * w * s.rz, twoG * (drr - meanRate) - 2.0 * w * s.rz,
            twoG * drz + w * (s.rr - s.zz)};
}

} // namespace hvi::material
