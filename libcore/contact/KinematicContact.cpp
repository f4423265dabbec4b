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

std::vector<uint8_t> KinematicContact::previousFlags(const ContactPoints& pts) const {
    std::vector<uint8_t> previous(pts.slaveCount(), 0);
    if (m_inContact.size() == pts.np + pts.nd.size()) {
        for (std::size_t k = 0; k < previous.size(); ++k) {
            previous[k] = m_inContact[pts.isParticle(k) ? k : pts.np + pts.pointOf(k)];
        }
    }
    return previous;
}

void KinematicContact::run(sph::ParticleSet& ps, const ParticleHalfStep& half, fe::ElementSet& el,
                           fe::NodeSet& nd, double dt, bool constrain) {
    m_surface.update(el, nd, m_options.axisymmetric);
    m_contactCount = 0;
    m_touchedParticles.clear();
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
    step.touching.assign(pts.slaveCount(), 0);
    step.pressedAsMaster.assign(nd.size(), 0);
    ConstraintSet constraints = buildConstraints(pts, found, dt, step.touching);
    solveImpulses(pts, constraints);
    markContacts(pts, constraints, step);
    shareHeat(pts, constraints, previousFlags(pts), m_energy);
    m_contactCount = step.contactCount;
    m_touchedParticles = std::move(step.touchedParticles);
    m_inContact.assign(pts.np + nd.size(), 0);
    for (std::size_t k = 0; k < pts.slaveCount(); ++k) {
        m_inContact[pts.isParticle(k) ? k : pts.np + pts.pointOf(k)] = step.touching[k];
    }
    for (std::size_t n = 0; n < nd.size(); ++n) {
        m_inContact[pts.np + n] |= step.pressedAsMaster[n];
    }
}

} // namespace hvi::contact
