// The deviatoric stress of a 2D point and its invariants, shared by the strength, failure and
// solver code.
//
// Axisymmetric (z axial, r radial): S_zz, S_rr, S_rz are stored; the hoop component follows
// from tracelessness, S_thth = -(S_zz + S_rr). Planar strain uses the same struct with
// x -> z, y -> r, and the out-of-plane component S_33 = -(S_xx + S_yy) in place of S_thth:
// in plane strain eps_33 = 0 but the deviator S_33 is not, so the formulas are identical.
// (This is the convention of Spheral's RZ solid SPH, hydrocode-notes.md section 2.1.)
//
// J2 = 1/2 S:S over all three diagonal components:
//   J2 = 1/2 (S_zz^2 + S_rr^2 + S_thth^2 + 2 S_rz^2),  sigma_eq = sqrt(3 J2) (von Mises).
// Leaving S_thth out is a classic RZ bug: a state with S_zz = S_rr != 0 would then read as
// far less stressed than it is.
//
// Units: GPa.
#pragma once

#include <cmath>

namespace hvi::material {

struct StressDeviator {
    double zz = 0.0; ///< S_zz (planar: S_xx) [GPa]
    double rr = 0.0; ///< S_rr (planar: S_yy) [GPa]
    double rz = 0.0; ///< S_rz (planar: S_xy) [GPa]

    /// S_thth = -(S_zz + S_rr) (planar: the out-of-plane S_33).
    double thetaTheta() const noexcept { return -(zz + rr); }

    /// J2 [GPa^2], including the hoop (out-of-plane) component.
    double secondInvariant() const noexcept {
        const double tt = thetaTheta();
        return 0.5 * (zz * zz + rr * rr + tt * tt) + rz * rz;
    }

    /// The largest principal value of S [GPa]: of the in-plane pair and the hoop component.
    double maxPrincipal() const noexcept {
        const double mean = 0.5 * (zz + rr);
        const double half = 0.5 * (zz - rr);
        return std::fmax(mean + std::sqrt(half * half + rz * rz), thetaTheta());
    }

    /// Von Mises equivalent stress sqrt(3 J2) [GPa].
    double vonMises() const noexcept { return std::sqrt(3.0 * secondInvariant()); }

    StressDeviator& operator*=(double factor) noexcept {
        zz *= factor;
        rr *= factor;
        rz *= factor;
        return *this;
    }
};

} // namespace hvi::material
