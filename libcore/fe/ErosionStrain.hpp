// The geometric strain that decides erosion, measured on an element's current shape.
//
// ANSYS Autodyn erodes an element on its "geometric strain" in one of two forms (ANSYS
// Explicit Dynamics / Autodyn help, "Erosion": Erode on Geometric Strain, Incremental or
// Instantaneous): incremental, the running integral of the equivalent strain rate, or
// instantaneous, computed each cycle from the element's current total strain. The
// incremental form counts every to and fro of an element that rings elastically: in the
// 1.7 mm rear wall of the 3.125 mm Whipple it reached 1.27 where the element's true strain was
// 0.016 (docs/notebook/fe-erosion.md), so the whole wall crept towards the erosion factor with no
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

#include <algorithm>
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

/// What the strain needs of an element's current stretch: the in-plane right Cauchy-Green
/// tensor C = F^T F (c11, c22, c12), det F and the hoop stretch.
struct Stretch {
    double c11 = 1.0, c22 = 1.0, c12 = 0.0, detF = 1.0, hoop = 1.0;
    /// det F > 0 and a positive hoop stretch (an inverted element has no strain: +inf).
    bool valid() const { return detF > 0.0 && hoop > 0.0; }
};

inline Stretch stretchOf(const QuadState& q, const ReferenceShape& ref, bool axisymmetric) {
    double fzz = 0.0, fzr = 0.0, frz = 0.0, frr = 0.0;
    for (std::size_t a = 0; a < 4; ++a) {
        fzz += q.z[a] * ref.bz[a];
        fzr += q.z[a] * ref.br[a];
        frz += q.r[a] * ref.bz[a];
        frr += q.r[a] * ref.br[a];
    }
    Stretch s;
    s.c11 = fzz * fzz + frz * frz;
    s.c22 = fzr * fzr + frr * frr;
    s.c12 = fzz * fzr + frz * frr;
    s.detF = fzz * frr - fzr * frz;
    if (axisymmetric) {
        s.hoop = 0.25 * (q.r[0] + q.r[1] + q.r[2] + q.r[3]) / ref.meanR;
    }
    return s;
}

/// The equivalent logarithmic strain of a stretch; +inf when it is not valid.
/// With e_i = ln(lambda_i) and e' its deviator, 2/3 e':e' = 2/9 sum_{i<j} (e_i - e_j)^2, so
/// only two logarithms are needed: a = e1 - e2 = ln(c1 / det F) (c2 = det F^2 / c1, which
/// stays accurate when the two in-plane stretches differ greatly) and b = e1 - e3 =
/// ln(c1 / lambda_theta^2) / 2.
inline double equivalentLogStrain(const Stretch& s) {
    if (!s.valid()) {
        return std::numeric_limits<double>::infinity();
    }
    const double half = 0.5 * (s.c11 - s.c22);
    const double c1 = 0.5 * (s.c11 + s.c22) + std::sqrt(half * half + s.c12 * s.c12);
    const double a = std::log(c1 / s.detF);
    const double b = 0.5 * std::log(c1 / (s.hoop * s.hoop));
    return std::sqrt((2.0 / 9.0) * (a * a + b * b + (b - a) * (b - a)));
}

/// The ratio limit of `strainCertainlyBelow` for a strain limit: exp(3 limit).
inline double stretchRatioLimit(double strainLimit) {
    return std::exp(3.0 * strainLimit);
}

/// True when the strain of a stretch is certainly below the limit whose
/// stretchRatioLimit is `ratioLimit`, decided without a logarithm or a square root (false says
/// nothing: evaluate the strain). Bound: for three log strains within a width
/// D = ln(c_max / c_min) / 2, sum_{i<j} (e_i - e_j)^2 <= 2 D^2, so the strain is at most
/// (2/3) D = ln(c_max / c_min) / 3; and c1 <= tr C <= 2 c1 gives c_max <= max(tr C,
/// lambda_theta^2), c_min >= min(det F^2 / tr C, lambda_theta^2). The bound overstates the
/// strain by at most ln(4) / 3 = 0.46, so nearly every element of a run passes this test and
/// skips the logarithms.
inline bool strainCertainlyBelow(const Stretch& s, double ratioLimit) {
    const double trace = s.c11 + s.c22;
    const double hoop2 = s.hoop * s.hoop;
    const double largest = std::max(trace, hoop2);
    return s.valid() && largest < ratioLimit * hoop2 &&
           largest * trace < ratioLimit * s.detF * s.detF;
}

/// Equivalent logarithmic strain of the element whose corners are now at q.z, q.r; +inf for
/// an inverted element (det F <= 0) or a hoop stretch that is not positive.
inline double instantaneousStrain(const QuadState& q, const ReferenceShape& ref,
                                  bool axisymmetric) {
    return equivalentLogStrain(stretchOf(q, ref, axisymmetric));
}

} // namespace hvi::fe
