#include "contact/KinematicContact.hpp"

#include "contact/ContactConstraints.hpp"
#include "contact/ContactSearch.hpp"
#include "contact/ContactSolver.hpp"

#include <algorithm>
#include <utility>

namespace hvi::contact {

KinematicContact::KinematicContact(ContactOptions options, std::vector<ContactBody> bodies)
    : m_options(options), m_bodies(std::move(bodies)) {}

void KinematicContact::resolve(sph::ParticleSet& ps, const ParticleHalfStep& half,
                               fe::ElementSet& el, fe::NodeSet& nd, double dt) {
    run(ps, half, el, nd, dt, true);
}

void KinematicContact::vote(sph::ParticleSet& ps, const ParticleHalfStep& half, fe::ElementSet& el,
                            fe::NodeSet& nd, double dt) {
    run(ps, half, el, nd, dt, false);
}

void KinematicContact::run(sph::ParticleSet& ps, const ParticleHalfStep& half, fe::ElementSet& el,
                           fe::NodeSet& nd, double dt, bool constrain) {
    m_surface.update(el, nd, m_options.axisymmetric);
    m_contactCount = 0;
    m_touchedParticles.clear();
    m_touchedNodes.clear();
    double maxSize = 0.0;
    for (const auto& b : m_bodies) {
        maxSize = std::max(maxSize, b.size);
    }
    const ContactPoints pts(ps, half, el, nd, m_surface, m_bodies, m_options);
    const std::vector<SlaveContacts> found = findCandidates(pts, dt, 2.5 * maxSize);
    m_stableDt = std::numeric_limits<double>::infinity();
    for (const auto& c : found) {
        m_stableDt = std::min(m_stableDt, c.dt);
    }
    if (!constrain) {
        return;
    }
    StepContacts step;
    ConstraintSet constraints = buildConstraints(pts, found, dt);
    solveImpulses(pts, constraints);
    markContacts(pts, constraints, step);
    shareHeat(pts, constraints, dt, m_energy);
    m_contactCount = step.contactCount;
    m_touchedParticles = std::move(step.touchedParticles);
    m_touchedNodes = std::move(step.touchedNodes);
}

} // namespace hvi::contact
