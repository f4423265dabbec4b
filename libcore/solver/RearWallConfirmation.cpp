#include "solver/RearWallConfirmation.hpp"

#include "assess/MaterialItems.hpp"
#include "assess/RearWallPerforation.hpp"

namespace hvi::solver {

io::Snapshot snapshotOf(double timeUs, long step, const sph::ParticleSet& ps,
                        const fe::FeSolid* fe) {
    io::Snapshot s;
    s.info.timeUs = timeUs;
    s.info.step = step;
    s.info.particleCount = ps.size();
    auto& p = s.particles;
    p.z = ps.z;
    p.r = ps.r;
    p.vz = ps.vz;
    p.vr = ps.vr;
    p.mass = ps.mass;
    p.density = ps.rho;
    p.pressure = ps.p;
    p.internalEnergy = ps.e;
    p.smoothingLength = ps.h;
    p.bodyId = ps.body;
    p.alive = ps.alive;
    if (ps.hasStrength()) {
        p.damage = ps.damage;
        p.plasticStrain = ps.plasticStrain;
    }
    if (fe) {
        io::FeFields f;
        const auto& nd = fe->nodes();
        const auto& el = fe->elements();
        f.nodes.z = nd.z;
        f.nodes.r = nd.r;
        f.nodes.vz = nd.vz;
        f.nodes.vr = nd.vr;
        f.nodes.mass = nd.mass;
        f.elements.connectivity = el.connectivity;
        f.elements.alive = el.alive;
        f.elements.damage = el.damage;
        f.elements.plasticStrain = el.plasticStrain;
        f.elements.pressure = el.p;
        f.elements.density = el.rho;
        f.elements.bodyId = el.body;
        s.info.hasFe = true;
        s.info.nodeCount = nd.size();
        s.info.elementCount = el.size();
        s.fe = std::move(f);
    }
    return s;
}

RearWallConfirmation::RearWallConfirmation(const scene::Scene& scene, const sph::ParticleSet& ps,
                                           const fe::FeSolid* fe)
    : m_first(snapshotOf(0.0, 0, ps, fe)), m_layout(assess::shieldLayout(scene, m_first)) {}

bool RearWallConfirmation::perforated(double timeUs, long step, const sph::ParticleSet& ps,
                                      const fe::FeSolid* fe) const {
    const io::Snapshot now = snapshotOf(timeUs, step, ps, fe);
    const auto wall =
        assess::rearWallPerforation(assess::materialItems(now, m_first), m_layout, m_criteria);
    return wall && wall->perforated;
}

} // namespace hvi::solver
