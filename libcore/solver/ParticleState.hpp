// The particles and what every package that moves them shares: their rates, the leapfrog's
// half-step state (solver/HalfStep.hpp), the evolving set (solver/EvolvingSet.hpp) and the
// alive count. SPH evaluates and integrates them, contact pushes them, the FE package adds
// the particles its eroded elements become, the deletion rule removes them.
#pragma once

#include "solver/EvolvingSet.hpp"
#include "solver/HalfStep.hpp"
#include "sph/ParticleSet.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace hvi::solver {

struct ParticleState {
    sph::ParticleSet set;
    sph::ParticleRates rates;
    HalfStep half;
    EvolvingSet evolving;
    std::size_t aliveCount = 0;

    HalfStep::Lanes lanes() { return half.lanes(set, rates); }
    void countAlive() {
        aliveCount =
            static_cast<std::size_t>(std::count(set.alive.begin(), set.alive.end(), uint8_t{1}));
    }
};

} // namespace hvi::solver
