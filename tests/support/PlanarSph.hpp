// One SPH evaluation of a hand-placed particle set (planar or axisymmetric): exact neighbour lists
// (no dormant skipping), zeroed rates, one SphHydro::evaluate. For unit tests of the pair terms.
#pragma once

#include "sph/NeighbourSearch.hpp"
#include "sph/SphHydro.hpp"

namespace hvi::test {

/// Evaluates `ps` with `hydro` in the given geometry (exact lists, no dormant skipping) into
/// `rates`; returns the package for its vote.
inline sph::SphHydro evaluateIn(bool axisymmetric, const sph::ParticleSet& ps,
                                sph::HydroOptions hydro, sph::ParticleRates& rates) {
    hydro.axisymmetric = axisymmetric;
    sph::NeighbourSearchOptions search;
    search.axisymmetric = axisymmetric;
    search.skipDormant = false;
    sph::NeighbourList list;
    sph::buildNeighbourList(ps, search, list);
    rates.resize(ps.size(), ps.hasStrength());
    rates.zero();
    sph::SphHydro hydroPackage(hydro);
    hydroPackage.evaluate(ps, list, rates);
    return hydroPackage;
}

/// Planar (plane strain).
inline sph::SphHydro evaluatePlanar(const sph::ParticleSet& ps, sph::HydroOptions hydro,
                                    sph::ParticleRates& rates) {
    return evaluateIn(false, ps, hydro, rates);
}

/// Axisymmetric: mirror ghosts across r = 0, the circumference-weighted pair terms and the hoop terms.
inline sph::SphHydro evaluateAxisymmetric(const sph::ParticleSet& ps, sph::HydroOptions hydro,
                                          sph::ParticleRates& rates) {
    return evaluateIn(true, ps, hydro, rates);
}

} // namespace hvi::test
