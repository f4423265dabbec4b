// One SPH evaluation of a hand-placed particle set (planar or axisymmetric): exact neighbour lists
// (no dormant skipping), zeroed rates, one SphHydro::evaluate. For unit tests of the pair terms.
#pragma once

#include "sph/NeighbourSearch.hpp"
#include "sph/SphHydro.hpp"

namespace hvi::test {

/// Evaluates `ps` with `hydro` (made planar) into `rates`; returns the package for its vote.
inline sph::SphHydro evaluatePlanar(const sph::ParticleSet& ps, sph::HydroOptions hydro,
                                    sph::ParticleRates& rates) {
    hydro.axisymmetric = false;
    sph::NeighbourSearchOptions search;
    search.axisymmetric = false;
    search.skipDormant = false;
    sph::NeighbourList list;
    sph::buildNeighbourList(ps, search, list);
    rates.resize(ps.size(), ps.hasStrength());
    rates.zero();
    sph::SphHydro hydroPackage(hydro);
    hydroPackage.evaluate(ps, list, rates);
    return hydroPackage;
}

/// The same in axisymmetric mode: mirror ghosts across r = 0, radius-weighted pair terms and
/// the hoop terms.
inline sph::SphHydro evaluateAxisymmetric(const sph::ParticleSet& ps, sph::HydroOptions hydro,
                                          sph::ParticleRates& rates) {
    hydro.axisymmetric = true;
    sph::NeighbourSearchOptions search;
    search.axisymmetric = true;
    search.skipDormant = false;
    sph::NeighbourList list;
    sph::buildNeighbourList(ps, search, list);
    rates.resize(ps.size(), ps.hasStrength());
    rates.zero();
    sph::SphHydro hydroPackage(hydro);
    hydroPackage.evaluate(ps, list, rates);
    return hydroPackage;
}

} // namespace hvi::test
