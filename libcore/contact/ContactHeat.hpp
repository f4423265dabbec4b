// Contact step 4 (contact/KinematicContact.hpp): which points were in contact, and the
// kinetic energy the impulses took, turned into heat.
//
// A new contact is a collision: the kinetic energy it takes becomes heat, so total energy is
// conserved. So is every contact with a particle: the compatible SPH energy equation has
// already paid, from internal energy, for the velocity the constraint removes. A lasting
// contact between FE nodes and segments only cancels the kick of the forces pressing the
// pair together, which the elements never paid for (their work follows the net motion,
// computed after the constraint): no heat. A node is in contact the step after it took an
// impulse as a slave or as a master: two touching surfaces have a constraint each way, and
// when the impulse moved from the one to the other (the struck plate's axis node pressing
// back on the flyer's, the step after the flyer's axis node had struck it) that pressing
// was booked as a new collision, and the axis element of an FE plate struck by another took
// 2.1 times its row's specific heat in the first blow.
//
// Each constraint's part of the energy: with J_k the impulses and v_n,k the normal
// velocities before (0) and after (1) the passes, sum_i m_i (v1_i^2 - v0_i^2) / 2 =
// sum_k J_k (v_n,k^0 + v_n,k^1) / 2 exactly (the velocity changes are linear in the J_k).
// Unlike the energy of each kick as it is made, this does not depend on the order of the
// passes: summing the kicks gave the first slave on a shared node the most heat, and the
// first SPH column on an FE face 1.36 times the specific heat of the fifth.
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
    std::vector<uint8_t> touching;        ///< per slave: touching, or held by an impulse
    std::vector<uint8_t> pressedAsMaster; ///< per node: took an impulse as a master
    std::vector<int32_t> touchedParticles; ///< particles whose velocity changed (may repeat)
    std::size_t contactCount = 0;         ///< constraints with an impulse
};

/// Running totals of the heat contact made [J].
struct ContactEnergy {
    double dissipated = 0.0;   ///< all of it
    double freeNodeHeat = 0.0; ///< the part that went into free nodes
};

/// Marks the slaves held by an impulse, the master nodes pressed, the particles touched.
void markContacts(const ContactPoints& points, const ConstraintSet& set, StepContacts& step);

/// Turns the kinetic energy each collision took into heat (`previous`: per slave, in
/// contact in the previous step), adding it to the specific energies and to `energy`.
void shareHeat(const ContactPoints& points, const ConstraintSet& set,
               const std::vector<uint8_t>& previous, ContactEnergy& energy);

} // namespace hvi::contact
