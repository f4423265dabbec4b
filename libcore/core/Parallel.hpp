// When a loop is worth threads. Below a few thousand items an OpenMP region costs more than it
// saves (fork/join and barriers run at every step), and on a loaded machine a descheduled
// thread stalls every barrier; small loops run on the calling thread. Results do not depend
// on this: every parallel loop computes each item independently (docs/formulation.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <omp.h>
#include <vector>

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

/// The indices k in [0, count) with keep(k), ascending, into `out` (resized to fit): each
/// thread counts and then writes its own contiguous block, so the result is the serial one at
/// any thread count. Threaded above kParallelMinItems.
template <class Keep>
void compactIndices(std::size_t count, Keep&& keep, std::vector<int32_t>& out) {
    if (count <= kParallelMinItems) {
        out.clear();
        for (std::size_t k = 0; k < count; ++k) {
            if (keep(k)) {
                out.push_back(static_cast<int32_t>(k));
            }
        }
        return;
    }
    std::vector<std::size_t> start(static_cast<std::size_t>(omp_get_max_threads()) + 1, 0);
#pragma omp parallel
    {
        const auto t = static_cast<std::size_t>(omp_get_thread_num());
        const auto threads = static_cast<std::size_t>(omp_get_num_threads());
        const std::size_t lo = count * t / threads, hi = count * (t + 1) / threads;
        std::size_t kept = 0;
        for (std::size_t k = lo; k < hi; ++k) {
            kept += keep(k) ? 1 : 0;
        }
        start[t + 1] = kept;
#pragma omp barrier
#pragma omp single
        {
            for (std::size_t u = 0; u < threads; ++u) {
                start[u + 1] += start[u];
            }
            out.resize(start[threads]);
        }
        std::size_t at = start[t];
        for (std::size_t k = lo; k < hi; ++k) {
            if (keep(k)) {
                out[at++] = static_cast<int32_t>(k);
            }
        }
    }
}

} // namespace hvi
