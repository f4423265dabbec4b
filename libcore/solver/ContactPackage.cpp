#include "solver/ContactPackage.hpp"

#include "core/Error.hpp"
#include "io/CheckpointFields.hpp"

namespace hvi::solver {

ContactPackage::ContactPackage(contact::ContactOptions options,
                               std::vector<contact::ContactBody> bodies, ParticleState& points,
                               FePackage& fe)
    : m_contact(options, std::move(bodies)), m_points(points), m_fe(fe) {}

void ContactPackage::constrain(double dt) {
    auto& solid = m_fe.solid();
    m_contact.resolve(m_points.set, m_points.half.contactView(), solid.elements(), solid.nodes(),
                      dt);
    // A dormant particle set moving by contact evolves from now on (its half-step state
    // equals its state, so the drift is all it has missed).
    m_points.evolving.include(m_contact.touchedParticles());
}

void ContactPackage::prepare(double dtGuess) {
    auto& solid = m_fe.solid();
    m_contact.vote(m_points.set, m_points.half.contactView(), solid.elements(), solid.nodes(),
                   dtGuess);
}

void ContactPackage::save(io::CheckpointState& s) const {
    io::putFlags(s, "contact_flags", m_contact.contactFlags());
    s.extra["contact_dt_us"] = m_contact.stableTimeStep();
    s.extra["contact_heat_J"] = m_contact.dissipatedEnergy();
    s.extra["free_node_heat_J"] = m_contact.freeNodeHeat();
}

void ContactPackage::restore(const io::CheckpointState& s) {
    // The flags' count follows the contact points of the last step, not a fixed set.
    const auto stored = s.ints.find("contact_flags");
    if (stored == s.ints.end()) {
        throw InputError("<checkpoint>", "/contact_flags", "missing",
                         "a checkpoint written by this version of hvi-run");
    }
    m_contact.restoreState(io::timeStepOf(s, "contact_dt_us"),
                           std::vector<uint8_t>(stored->second.begin(), stored->second.end()));
    m_contact.restoreDissipatedEnergy(s.extra.at("contact_heat_J"));
    m_contact.restoreFreeNodeHeat(s.extra.value("free_node_heat_J", 0.0));
}

} // namespace hvi::solver
