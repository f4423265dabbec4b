// The geometric strain that decides erosion, measured on an element's current shape.
//
// ANSYS Autodyn erodes an element on its "geometric strain" in one of two forms (ANSYS
// Explicit Dynamics / Autodyn help, "Erosion": Erode on Geometric Strain, Incremental or
// Instantaneous): incremental, the running integral of the equivalent strain rate, or
// instantaneous, computed each cycle from the element's current total strain. The
// incremental form counts every to and fro of an element that rings elastically: in the
// 1.7 mm rear wall of the 3.125 mm Whipple it reached 1.27 where the element's true strain was
// 0.016 (docs/fe-erosion.md), so the whole wall crept towards the erosion factor with no
// deformation at all. Here the instantaneous form is the von Mises equivalent of the
// logarithmic (Hencky) strain of the mean deformation gradient,
//   F = sum_a x_a (x) dN_a/dX   (in-plane, at the reference centroid; exact for linear fields),
//   C = F^T F with eigenvalues c1, c2;  e = (ln c1 / 2, ln c2 / 2, ln(r / R))  (hoop stretch
//   from the mean corner radii, axisymmetric; 0 in plane strain),
//   eps = sqrt(2/3 e':e'),  e' = e - tr(e)/3,
// which is zero for rigid motions and pure volume changes, and (2/3) |ln lambda| for a
// stretch lambda in one direction with the others held (e = (ln lambda, 0, 0)).
// Units: dimensionless; coordinates in mm, gradients in 1/mm.
#pragma once

#include "fe/QuadKinematics.hpp"

#include <array>
#include <cmath>
#include <limits>

namespace hvi::fe {

/// What the instantaneous strain needs of an element's reference (initial) shape.
struct ReferenceShape {
    std::array<double, 4> bz{}, br{}; ///< dN_a/dZ, dN_a/dR at the reference centroid [1/mm]
    double meanR = 0.0;               ///< mean corner radius [mm]
};

inline ReferenceShape referenceShape(const QuadState& q) {
    const QuadGeometry g = quadGeometry(q);
    return {g.bz, g.br, g.meanR};
}

/// Equivalent logarithmic strain of the element whose corners are now at q.z, q.r; +inf for
/// an inverted element (det F <= 0) or a hoop stretch that is not positive.
inline double instantaneousStrain(const QuadState& q, const ReferenceShape& ref,
                                  bool axisymmetric) {
    double fzz = 0.0, fzr = 0.0, frz = 0.0, frr = 0.0;
    for (std::size_t a = 0; a < 4; ++a) {
        fzz += q.z[a] * ref.bz[a];
        fzr += q.z[a] * ref.br[a];
        frz += q.r[a] * ref.bz[a];
        frr += q.r[a] * ref.br[a];
    }
    const double detF = fzz * frr - fzr * frz;
    double hoopStretch = 1.0;
    if (axisymmetric) {
        hoopStretch = 0.25 * (q.r[0] + q.r[1] + q.r[2] + q.r[3]) / ref.meanR;
    }
    if (!(detF > 0.0) || !(hoopStretch > 0.0)) {
        return std::numeric_limits<double>::infinity();
    }
    // Eigenvalues of the 2x2 right Cauchy-Green tensor; the smaller from det C = (det F)^2,
    // which stays accurate when the two differ greatly.
    const double c11 = fzz * fzz + frz * frz, c22 = fzr * fzr + frr * frr;
    const double c12 = fzz * fzr + frz * frr;
    const double half = 0.5 * (c11 - c22);
    const double c1 = 0.5 * (c11 + c22) + std::sqrt(half * half + c12 * c12);
    const double c2 = detF * detF / c1;
    const double e1 = 0.5 * std::log(c1), e2 = 0.5 * std::log(c2);
    const double e3 = std::log(hoopStretch);
    const double mean = (e1 + e2 + e3) / 3.0;
    const double d1 = e1 - mean, d2 = e2 - mean, d3 = e3 - mean;
    return std::sqrt((2.0 / 3.0) * (d1 * d1 + d2 * d2 + d3 * d3));
}

} // namespace hvi::fe
