// Kinematics of a 4-node quadrilateral with one-point (centroid) integration in the (z, r)
// plane: area, the uniform-strain gradient operator, the velocity gradient and the
// hourglass base vectors.
//
// References:
//   Flanagan D.P., Belytschko T. (1981), "A uniform strain hexahedron and quadrilateral with
//   orthogonal hourglass control", Int. J. Numer. Meth. Eng. 17:679-706: eq. (12)-(14) for the
//   mean gradient b_a = dN_a/dx at the centroid (exact for linear fields), eq. (40)-(45) for
//   the hourglass base vector gamma_a = (Gamma_a - (Gamma . x) b_x,a - (Gamma . y) b_y,a) / 4
//   with Gamma = (1, -1, 1, -1), orthogonal to every linear velocity field.
//   Hallquist J.O., LS-DYNA Theory Manual (2006), section 7 ("Two-dimensional solid elements",
//   volume-weighted axisymmetric element): the hoop strain rate v_r / r at the centroid and the
//   element volume 2 pi * integral(r dA).
//
// Node order is counter-clockwise in the (z, r) plane (z plays x, r plays y), so a valid
// element has a positive area. Units: mm, km/s (= mm/us), 1/us.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace hvi::fe {

/// The corner coordinates and velocities of one element, gathered from the node arrays.
struct QuadState {
    std::array<double, 4> z{}, r{}, vz{}, vr{};
};

/// What one-point integration needs of an element's geometry.
struct QuadGeometry {
    double area = 0.0;          ///< [mm^2], > 0 for a valid counter-clockwise element
    double centroidR = 0.0;     ///< area centroid r = integral(r dA) / A [mm]
    double meanR = 0.0;         ///< mean of the corner radii [mm] (hoop rate, hoop force)
    std::array<double, 4> bz{}; ///< dN_a/dz at the centroid [1/mm]
    std::array<double, 4> br{}; ///< dN_a/dr at the centroid [1/mm]
    double maxDiagonal = 0.0;   ///< longest diagonal [mm] (the time-step length A / d_max)
};

inline QuadGeometry quadGeometry(const QuadState& q) {
    QuadGeometry g;
    const auto& z = q.z;
    const auto& r = q.r;
    // Flanagan & Belytschko eq. (14): A = ((z3 - z1)(r4 - r2) + (z2 - z4)(r3 - r1)) / 2
    // (indices 1-4 here 0-3).
    g.area = 0.5 * ((z[2] - z[0]) * (r[3] - r[1]) + (z[1] - z[3]) * (r[2] - r[0]));
    const double inv2A = 0.5 / g.area;
    g.bz = {inv2A * (r[1] - r[3]), inv2A * (r[2] - r[0]), inv2A * (r[3] - r[1]),
            inv2A * (r[0] - r[2])};
    g.br = {inv2A * (z[3] - z[1]), inv2A * (z[0] - z[2]), inv2A * (z[1] - z[3]),
            inv2A * (z[2] - z[0])};
    // Area centroid r of the polygon (shoelace formula for the first moment).
    double moment = 0.0;
    for (int a = 0; a < 4; ++a) {
        const int b = (a + 1) % 4;
        const double cross = z[a] * r[b] - z[b] * r[a];
        moment += (r[a] + r[b]) * cross;
    }
    g.centroidR = moment / (6.0 * g.area);
    g.meanR = 0.25 * (r[0] + r[1] + r[2] + r[3]);
    // Squares compared first: one square root instead of two (std::hypot is slow).
    const double d1 = (z[2] - z[0]) * (z[2] - z[0]) + (r[2] - r[0]) * (r[2] - r[0]);
    const double d2 = (z[3] - z[1]) * (z[3] - z[1]) + (r[3] - r[1]) * (r[3] - r[1]);
    g.maxDiagonal = std::sqrt(std::max(d1, d2));
    return g;
}

/// The velocity gradient L = grad v at the centroid: L_zz = dvz/dz, L_zr = dvz/dr, ...
struct QuadVelocityGradient {
    double zz = 0.0, zr = 0.0, rz = 0.0, rr = 0.0;
};

inline QuadVelocityGradient velocityGradient(const QuadState& q, const QuadGeometry& g) {
    QuadVelocityGradient l;
    for (int a = 0; a < 4; ++a) {
        l.zz += g.bz[a] * q.vz[a];
        l.zr += g.br[a] * q.vz[a];
        l.rz += g.bz[a] * q.vr[a];
        l.rr += g.br[a] * q.vr[a];
    }
    return l;
}

/// Hourglass base vector gamma_a (Flanagan & Belytschko eq. 45, 2D form): orthogonal to the
/// linear fields (sum_a gamma_a = 0, sum_a gamma_a z_a = sum_a gamma_a r_a = 0), so the
/// hourglass velocity sum_a gamma_a v_a measures only the zero-energy (hourglass) mode.
inline std::array<double, 4> hourglassBase(const QuadState& q, const QuadGeometry& g) {
    constexpr std::array<double, 4> kGamma{1.0, -1.0, 1.0, -1.0};
    double gz = 0.0, gr = 0.0;
    for (int a = 0; a < 4; ++a) {
        gz += kGamma[a] * q.z[a];
        gr += kGamma[a] * q.r[a];
    }
    std::array<double, 4> gamma{};
    for (int a = 0; a < 4; ++a) {
        gamma[a] = 0.25 * (kGamma[a] - gz * g.bz[a] - gr * g.br[a]);
    }
    return gamma;
}

} // namespace hvi::fe
