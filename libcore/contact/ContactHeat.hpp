// Contact step 4 (contact/KinematicContact.hpp): which points were in contact, and the
// kinetic energy the impulses took, turned into heat.
//
// The heat of a constraint is the kinetic energy its impulse J took, less the part of it
// that no internal energy had paid for:
//     Q = -J ((v_n^0 + v_n^1) / 2 - k_n),
// with v_n^0 and v_n^1 the relative normal velocities before and after the passes and k_n
// the part of v_n^0 made by this step's first half kick of the FE forces on its nodes (the
// slave node's kick along n less the master nodes' weighted kicks; nothing for particles).
// Why: sum_i m_i (v1_i^2 - v0_i^2) / 2 = sum_k J_k (v_n,k^0 + v_n,k^1) / 2 exactly (the
// velocity changes are linear in the J_k), and it does not depend on the order of the
// passes (summing each kick's energy as it was made gave the first slave on a shared node
// the most heat, and the first SPH column on an FE face 1.36 times the specific heat of the
// fifth). A particle's half kick is paid for: the SPH energy equation works with the
// predicted velocity, which carries the kick, so a particle held against a wall pays 2 m k^2
// a step from its internal energy and the constraint hands it back. An element pays only
// through the motion its nodes keep after the constraint (fe/FeSolid.hpp: its strain rate is
// that of the half-step velocities), so for a node with velocity v at the start of the step,
// kick k and half-step velocity v' after the impulse, energy is conserved over the step when
// the heat is m (v + k)^2 / 2 - m v'^2 / 2 + k . m (v' - v - k): the kinetic energy taken,
// plus k . J_node. A node pressed against a surface step after step (v = k, v' = 0) then
// makes no heat (booking all the kinetic energy taken would make 2 m k^2 every step, a
// runaway where eroding layers squeeze a particle: docs/notebook/contact-heat.md). A new
// collision (v = v_n before, v' = 0) makes m (v^2 - k^2) / 2: the collision's heat less a
// half kick's worth.
//
// The heat is shared in proportion to the masses that take it (the slave particle, the
// elements of a slave node, a free node itself; the master segments' elements by the
// footprint's shares, the elements around the master nodes by the nodes' shares, or the
// master particle), so both sides rise by the same specific energy, as the two sides of a
// symmetric impact of like materials do (u_p^2 / 2 each). A free node is eroded material:
// its share joins the eroded energy ledger (freeNodeHeat), as its internal energy did when
// it eroded.
//
// Units: mm, us, mg (km/s, J = mg km^2/s^2).
#pragma once

#include "contact/ContactConstraints.hpp"

#include <cstdint>
#include <vector>

namespace hvi::contact {

/// Who was in contact in a step.
struct StepContacts {
    std::vector<int32_t> touchedParticles; ///< particles whose velocity changed (may repeat)
    std::vector<int32_t> touchedNodes;     ///< FE nodes whose velocity changed (may repeat)
    std::size_t contactCount = 0;          ///< constraints with an impulse
};

/// Running totals of the heat contact made [J].
struct ContactEnergy {
    double dissipated = 0.0;   ///< all of it
    double freeNodeHeat = 0.0; ///< the part that went into free nodes
};

/// Counts the constraints with an impulse and lists the particles they touched.
void markContacts(const ContactPoints& points, const ConstraintSet& set, StepContacts& step);

/// Turns the kinetic energy the impulses of a step dt [us] took into heat (header comment),
/// adding it to the specific energies and to `energy`.
void shareHeat(const ContactPoints& points, const ConstraintSet& set, double dt,
               ContactEnergy& energy);

} // namespace hvi::contact
