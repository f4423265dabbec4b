// The SPH hydrodynamics package: pair forces, compatible energy, continuity, smoothing-length
// evolution and the corrected velocity gradient that the strength package consumes.
//
// Formulation (docs/formulation.md derives every term):
//   axisymmetric (z, r), each particle a ring of true mass m, area mass A = m / (2 pi r):
//     dv_i/dt = sum_j [w_own,ij B_i + A_j B_j - w_pair,ij Pi_ij I] . grad W_ij  +  hoop_i
//     w_own,ij = m_j / (2 pi r_i),  w_pair,ij = (w_own,ij + A_j) / 2
//     B       = sigma / rho^2,  sigma = S - p I  (in-plane components)
//     hoop_i  = [-(sigma_thth,i / rho_i) g_r,i
//                + phi_i sum_j (w_pair,ij - A_j) Pi_ij dW_ij/dr_i] e_r  (viscous hoop part)
//     g_i     = (2 / rho_i) sum_j (w_pair,ij - A_j) grad W_ij  ~ e_r / r
//     phi_i   = 1 - c_r / max(c_z, c_r),  c_a = max(-L_aa, 0)  (radial share of compression)
//   Each stress acts over its own particle's circumference (Brookshaw 2003; Garcia-Senz,
//   Relano, Cabezon & Bravo 2009, MNRAS 392:346; Spheral src/SPH/SPHHydroBaseGSRZ.cc): the
//   pair force m_i m_j (B_i / 2 pi r_i + B_j / 2 pi r_j) . grad W is antisymmetric, so total
//   z-momentum is conserved to round-off, and the neighbours' part is the area-weighted
//   (planar) divergence, consistent up to the axis. The own part adds B_i . (rho_i g_i), the
//   sigma_rr / (rho r) and sigma_rz / (rho r) of the cylindrical divergence; hoop_i adds
//   -sigma_thth / (rho r) (Petschek & Libersky 1993, JCP 109:76). Using the same discrete g
//   in both makes a uniform pressure exert exactly no radial force, and a field varying
//   along z only, or a linear velocity field, none either (docs/formulation.md,
//   tests/unit/sph/AxisForces_test.cpp).
//   The energy equation is the compatible one (Owen 2004-style pairwise work split), so total
//   energy is conserved by the semi-discrete equations; the stress work is split with the
//   area weights (docs/formulation.md, Energy):
//     de_i/dt = -sum_j v_ij . (A_j B_i + (w_own,ij - A_j)(B_i - B_j)/2
//                              - w_pair,ij Pi_ij/2 I) . grad W_ij  -  v_r,i hoop_i
//   Every term of it is linear in the velocities; with HydroOptions::keepPairWork each pair's
//   coefficients are kept for the half kicks to pay them with their own mean velocities
//   (sph/PairWork.hpp, the compatible energy update).
//   Next to the axis (docs/formulation.md, The axis): a particle with a mirror among its
//   neighbours takes off the axial excess of its own-stress and viscous sums over the
//   area-weighted ones,
//     X_i = sum_j [(w_own,ij - A_j) B_zz,i - (w_pair,ij - A_j) Pi_ij] dW_ij/dz,
//   and the same excess of its axial work, so its axial force and heating are the
//   area-weighted (planar) ones, as every pair term is in Spheral's RZ SPH: a flow that varies
//   along z only stays the same at every radius (tests/verification/AxisFlyerPlate_test.cpp).
//   X is zero on a lattice symmetric about r_i, so only those particles change. The price:
//   their axial forces are not antisymmetric, so z-momentum is exact only away from the axis,
//   and energy is not exact either (measured drifts: docs/notebook/axis.md).
//   Planar mode: w_own = w_pair = A_j = m_j (mass per unit depth), no hoop term.
// Artificial viscosity: Monaghan & Gingold (1983), Monaghan (1992) eq. 4.1:
//   Pi_ij = (-alpha cbar mu + beta mu^2) / rhobar for approaching pairs,
//   mu = hbar v_ij.x_ij / (|x_ij|^2 + eta^2 hbar^2).
// Velocity gradient: SPH estimate with particle volumes V_j = A_j / rho_j and the linear
// correction matrix (Randles & Libersky 1996; Spheral's correctVelocityGradient), exact for
// linear velocity fields. Continuity: drho/dt = -rho (tr L + D_thth) with D_thth = v_r g_r,
// except where a solid particle's neighbours differ from it in density by more than 1.5
// (fragmented debris beside compressed material): there drho/dt = sum_j A_j v_ij . grad W
// - rho D_thth, the pairwise rate the compatible energy equation pays pressure work for.
// The corrected, volume-weighted divergence weighs an expanded neighbour by the void it
// spans (V_j = A_j / rho_j) and, with few neighbours on one side, turns their sliding into
// compression the energy equation never pays for (tests/verification/StrayStates_test.cpp;
// measurements in docs/notebook/stray-states.md). A gas keeps the corrected rate
// everywhere: the Noh problem's sixteenfold shock needs it at its front.
// Tensile instability (particles in tension clump and the material tears too early):
// Monaghan's artificial stress (Monaghan 2000, JCP 159:290; Gray, Monaghan & Swift 2001,
// CMAME 190:6641, eqs. 23-27 for elastic solids). Each particle carries R_i, the tensile part
// of its in-plane stress: in the principal frame R'_aa = -epsilon sigma'_aa / rho^2 where
// sigma'_aa > 0, else 0, rotated back. A pair adds f_ij^4 (R_i + R_j) to B_i + B_j, with
// f_ij = W(r_ij) / W(dp) (dp the particle spacing, h-bar / smoothing factor): a repulsion
// between particles in tension that is 1 at the spacing (where it cancels over a uniform
// lattice), grows steeply as a pair closes in below it (the clumping it opposes) and fades
// beyond it; nothing in compression. The energy equation carries
// f^n R_i next to B_i, so the compatible split still conserves energy exactly. Off
// (epsilon = 0) by default; see docs/formulation.md for the measured effect.
// Time step (Monaghan 1992): dt_i = h_i / (c_i + 1.2 (alpha c_i + beta max_j |mu_ij|)),
// and dt_i <= sqrt(h_i / |a_i|); the caller multiplies by the Courant factor.
//
// Units: mm, us, mg (km/s, GPa, g/cm^3, MJ/kg); see docs/conventions.md.
#pragma once

#include "sph/Kernel.hpp"
#include "sph/NeighbourSearch.hpp"
#include "sph/PairWork.hpp"
#include "sph/ParticleSet.hpp"

#include <cstdint>
#include <vector>

namespace hvi::sph {

struct HydroOptions {
    bool axisymmetric = true;
    KernelType kernel = KernelType::CubicSpline;
    double avAlpha = 1.0;
    double avBeta = 2.0;
    double avEta2 = 0.01; ///< eta^2 in mu's denominator: keeps mu finite for close pairs
    /// Artificial stress against the tensile instability (epsilon; 0: off; file comment).
    double artificialStress = 0.0;
    /// The particle spacing in units of h (1 / smoothing_length_factor): the distance at
    /// which the artificial stress has its full strength.
    double spacingOverH = 1.0 / 1.3;
    /// Per scene body: 1 where the body's particles take the pairwise density rate when a
    /// neighbour's density differs from theirs by more than 1.5 (header comment,
    /// Continuity); empty or 0: always the corrected one.
    std::vector<uint8_t> pairwiseContinuityAtContrast;
    /// Keep each pair's work per unit relative velocity (sph/PairWork.hpp), for the
    /// compatible energy update of the half kicks; false: the energy takes the rate alone.
    bool keepPairWork = false;
};

/// What a particle contributes to its neighbours' sums, packed so a neighbour is two cache
/// lines (the first holds all the support test needs). B = sigma / rho^2 is formed once per
/// evaluation instead of once per pair.
struct alignas(64) PairData {
    double z, r, h, mass, vz, vr, rho, cs;
    double bzz, brr, brz; ///< B = sigma / rho^2, in-plane components [GPa cm^6/g^2]
    double areaMass;      ///< A = m / (2 pi r) (planar: m) [mg/mm]
    double volume;        ///< A / rho [mm^2]
    double azz, arr, arz; ///< artificial stress R / rho^2 [GPa cm^6/g^2] (0 when off)
};

/// The pairs of one evaluation: those inside the support, and those the vectorised loop
/// computed (each particle's padded to a multiple of its lanes with null pairs).
struct PairCounts {
    std::size_t inside = 0;
    std::size_t computed = 0;
};

/// Flops of one computed pair of the hydro pair loop, counted from its source (a fused
/// multiply-add as two; each of its four divisions and its square root as one, though each
/// costs the divider several cycles), without the artificial stress: the assumption behind
/// the benchmark's flop rate (docs/performance.md).
inline constexpr double kPairFlops = 130.0;

class SphHydro {
public:
    explicit SphHydro(HydroOptions options) : m_options(options) {}

    /// Adds this package's rates for the active particles of `list` into `rates` (which the
    /// caller zeroes), and records the largest stable time step (before the Courant factor).
    /// `changed` (sorted or not) lists the particles whose state may differ from the last
    /// call; null means all (and the first call always packs all). `slots`: only the active
    /// particles of these slots of `list.active` (time-step bins; null: all of them), whose
    /// entries alone particleSteps() then sets.
    void evaluate(const ParticleSet& particles, const NeighbourList& list, ParticleRates& rates,
                  const std::vector<int32_t>* changed = nullptr,
                  const std::vector<int32_t>* slots = nullptr);

    /// h / signal speed, minimised over the particles of the last evaluate() [us].
    double stableTimeStep() const { return m_stableDt; }
    /// Sets the vote of the evaluation a checkpoint was taken after (an exact resume).
    void restoreStableTimeStep(double dt, int32_t particle) {
        m_stableDt = dt;
        m_limitingParticle = particle;
    }
    /// The particle that set stableTimeStep() (for the progress line).
    int32_t limitingParticle() const { return m_limitingParticle; }
    /// Each active particle's own vote in the last evaluate(), in the list's active order
    /// [us] (+inf: it sets no limit); empty after a resume until the next evaluate().
    const std::vector<double>& particleSteps() const { return m_particleSteps; }
    /// The pairs of the last evaluate().
    const PairCounts& pairCounts() const { return m_pairs; }
    /// The pair work of the last evaluate() (HydroOptions::keepPairWork; empty otherwise),
    /// and its way back from a checkpoint.
    const PairWork& pairWork() const { return m_work; }
    PairWork& pairWork() { return m_work; }

    const HydroOptions& options() const { return m_options; }

private:
    HydroOptions m_options;
    double m_stableDt = 0.0;
    int32_t m_limitingParticle = -1;
    std::vector<PairData> m_data; ///< per particle, refreshed by every evaluate()
    std::vector<double> m_particleSteps;
    PairCounts m_pairs;
    PairWork m_work;
};

} // namespace hvi::sph
