#include "solver/Ledger.hpp"

#include <cmath>

namespace hvi::solver {

Totals Ledger::totals(const sph::ParticleSet& ps, const fe::FeSolid* fe,
                      const contact::KinematicContact* contact, std::size_t active) const {
    Totals t;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i]) {
            t.deleted += sph::isUnusedSlot(ps.alive[i], ps.mass[i]) ? 0 : 1;
            continue;
        }
        ++t.alive;
        const double m = ps.mass[i];
        t.kinetic += 0.5 * m * (ps.vz[i] * ps.vz[i] + ps.vr[i] * ps.vr[i]);
        t.internal += m * ps.e[i];
        t.mass += m;
        t.momentumZ += m * ps.vz[i];
    }
    t.deletedEnergy = m_account.deletedEnergy;
    if (fe) {
        const auto& nd = fe->nodes();
        for (std::size_t k = 0; k < nd.size(); ++k) {
            if (nd.alive[k]) {
                const double m = nd.mass[k];
                t.kinetic += 0.5 * m * (nd.vz[k] * nd.vz[k] + nd.vr[k] * nd.vr[k]);
                t.mass += m;
                t.momentumZ += m * nd.vz[k];
            }
        }
        const auto& el = fe->elements();
        for (std::size_t i = 0; i < el.size(); ++i) {
            if (el.alive[i]) {
                t.internal += el.mass[i] * el.e[i];
            }
        }
        t.deletedEnergy += fe->erodedEnergy() + (contact ? contact->freeNodeHeat() : 0.0);
        t.erodedElements = fe->erodedCount();
    }
    t.deletedMass = m_account.deletedMass;
    t.deletedMomentumZ = m_account.deletedMomentumZ;
    t.active = active;
    return t;
}

double Ledger::energyError(const Totals& t) const {
    const double e0 = m_account.initialEnergy;
    const double scale = std::fabs(e0) > 0.0 ? std::fabs(e0) : 1.0;
    return (t.kinetic + t.internal + t.deletedEnergy - e0) / scale;
}

} // namespace hvi::solver
