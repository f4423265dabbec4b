// J2 (von Mises) radial return for a 2D point, axisymmetric or planar strain.
//
// Reference: M.L. Wilkins, "Calculation of elastic-plastic flow", Methods in Computational
// Physics 3 (1964) 211-263 (the radial-return scaling); J.C. Simo and T.J.R. Hughes,
// "Computational Inelasticity" (Springer, 1998), the return-mapping chapter, where the same
// step is the closest-point projection for J2 plasticity at a fixed yield stress.
//
// After the elastic trial update S_trial, if sigma_eq = sqrt(3 J2(S_trial)) > Y, scale
// S <- (Y / sigma_eq) S, which lands exactly on the yield surface with the direction of S
// kept. The equivalent plastic strain increment consistent with that return is
//   d eps_p = (sigma_eq - Y) / (3 G)
// (the trial overshoot divided by 3G, since an equivalent plastic strain d eps_p relaxes
// sigma_eq by 3 G d eps_p). Y is taken at the start of the step (no iteration on hardening),
// the usual explicit-hydrocode choice: the hardening over one step is far below Y.
//
// J2 includes the hoop / out-of-plane component (StressDeviator.hpp), so the same code
// serves the axisymmetric and the planar-strain solver.
//
// Units: S, Y, G in GPa; d eps_p dimensionless.
#pragma once

#include "material/strength/StressDeviator.hpp"

#include <cstddef>
#include <span>
#include <stdexcept>

namespace hvi::material {

/// Returns S onto the yield surface of radius Y [GPa] (in place) and gives the equivalent
/// plastic strain increment. Y <= 0 (melted or failed material) zeroes S. G > 0 [GPa].
inline double radialReturn(StressDeviator& s, double yieldStress, double shearModulus) noexcept {
    const double sigmaEq = s.vonMises();
    if (yieldStress <= 0.0) {
        s = StressDeviator{};
        return sigmaEq / (3.0 * shearModulus);
    }
    if (sigmaEq <= yieldStress) {
        return 0.0;
    }
    s *= yieldStress / sigmaEq;
    return (sigmaEq - yieldStress) / (3.0 * shearModulus);
}

/// Batch form over structure-of-arrays storage: returns every point onto its own yield
/// surface and adds the plastic strain increment to plasticStrain. All spans one length
/// (checked once; throws std::invalid_argument).
inline void radialReturn(std::span<double> szz, std::span<double> srr, std::span<double> srz,
                         std::span<const double> yieldStress, double shearModulus,
                         std::span<double> plasticStrain) {
    const std::size_t n = szz.size();
    if (srr.size() != n || srz.size() != n || yieldStress.size() != n ||
        plasticStrain.size() != n) {
        throw std::invalid_argument("radialReturn: spans differ in length");
    }
    for (std::size_t i = 0; i < n; ++i) {
        StressDeviator s{szz[i], srr[i], srz[i]};
        plasticStrain[i] += radialReturn(s, yieldStress[i], shearModulus);
        szz[i] = s.zz;
        srr[i] = s.rr;
        srz[i] = s.rz;
    }
}

} // namespace hvi::material
