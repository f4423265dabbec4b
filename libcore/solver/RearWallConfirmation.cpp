#include "solver/RearWallConfirmation.hpp"

#include "assess/MaterialItems.hpp"
#include "assess/RearWallPerforation.hpp"
#include "solver/StateView.hpp"

namespace hvi::solver {

io::Snapshot snapshotOf(double timeUs, long step, const sph::ParticleSet& ps,
                        const fe::FeSolid* fe) {
    io::Snapshot s;
    s.info.timeUs = timeUs;
    s.info.step = step;
    s.info.particleCount = ps.size();
    std::vector<double> deviator;
    const io::ParticleFieldsView particles = particleFieldsOf(ps, deviator);
    s.particles = io::ownedOf(particles);
    if (fe) {
        // The stored geometric strain: the rule does not read it, and the current one costs a
        // pass over every element (fe::FeSolid::erosionStrain).
        const io::FeFieldsView elements = feFieldsOf(*fe, fe->elements().geometricStrain);
        s.fe = io::ownedOf(elements);
        s.info.hasFe = true;
        s.info.nodeCount = fe->nodes().size();
        s.info.elementCount = fe->elements().size();
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
