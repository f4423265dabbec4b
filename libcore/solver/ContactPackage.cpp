#include "solver/ContactPackage.hpp"

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
    m_fe.wakeAtNodes(m_contact.touchedNodes());
}

void ContactPackage::prepare(double dtGuess) {
    auto& solid = m_fe.solid();
    m_contact.vote(m_points.set, m_points.half.contactView(), solid.elements(), solid.nodes(),
                   dtGuess);
}

void ContactPackage::save(io::CheckpointState& s) const {
    s.extra["contact_dt_us"] = m_contact.stableTimeStep();
    s.extra["contact_heat_J"] = m_contact.dissipatedEnergy();
    s.extra["free_node_heat_J"] = m_contact.freeNodeHeat();
}

void ContactPackage::restore(const io::CheckpointState& s) {
    m_contact.restoreStableTimeStep(io::timeStepOf(s, "contact_dt_us"));
    m_contact.restoreDissipatedEnergy(s.extra.at("contact_heat_J"));
    m_contact.restoreFreeNodeHeat(s.extra.value("free_node_heat_J", 0.0));
}

} // namespace hvi::solver
