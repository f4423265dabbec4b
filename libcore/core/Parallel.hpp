// When a loop is worth threads. Below a few thousand items an OpenMP region costs more than it
// saves (fork/join and barriers run at every step), and on a loaded machine a descheduled
// thread stalls every barrier; small loops run on the calling thread. Results do not depend
// on this: every parallel loop computes each item independently (docs/formulation.md).
#pragma once

#include <cstddef>

namespace hvi {

inline constexpr std::size_t kParallelMinItems = 4096;

/// The same for loops whose items each cost thousands of operations (a particle's pair sums
/// over its twenty-odd neighbours, its neighbour-list row): there a few hundred items already
/// outweigh the fork/join. Measured on the default case (HITF03147-2, 0.04 mm, about 2 400
/// active particles), whose pair loop ran on one thread under the general threshold.
inline constexpr std::size_t kParallelMinHeavyItems = 256;

/// body(k) for k in [0, count): threaded above kParallelMinItems, otherwise a plain loop that
/// does not enter the OpenMP runtime at all (an `if(false)` parallel region still builds a
/// one-thread team, which costs more than a tile of a few hundred light items; the FE update
/// calls the material pipeline once per such tile, from inside its own parallel region).
template <class Body>
void parallelFor(std::size_t count, Body&& body) {
    if (count > kParallelMinItems) {
#pragma omp parallel for schedule(static)
        for (std::size_t k = 0; k < count; ++k) {
            body(k);
        }
    } else {
        for (std::size_t k = 0; k < count; ++k) {
            body(k);
        }
    }
}

} // namespace hvi
