// Cell-list neighbour search in the (z, r) plane, O(N), with mirror ghosts across the axis
// and the "compute only what the scene needs" rule.
//
// Every step the alive particles are binned into square cells of side >= the largest kernel
// support (kappa * h_max), so all neighbours of a particle lie in its own and the 8
// surrounding cells. Only *active* cells are searched: cells holding an awake particle
// (moving, or carrying pressure or stress) and their neighbours. A particle outside them is
// at rest in its reference state with all its neighbours also at rest and unstressed, so its
// rates are exactly zero and skipping it changes nothing (tests check this bitwise).
//
// Axisymmetric mode: particles within one support of the axis get a mirror image at
// (z, -r) (a reflecting boundary: Spheral's AxisBoundaryRZ does the same), so kernel sums
// near the axis are not truncated. Ghosts are addressed as indices >= n with
// `source[j]` the particle they mirror and `sign[j] = -1` (r, v_r and S_rz change sign).
//
// Neighbour lists are full (each particle lists all of its neighbours) and built in a fixed
// order (cells scanned in index order), so every particle's sums are formed in the same
// order whatever the thread count: results are bitwise identical for 1 and N threads.
#pragma once

#include "sph/ParticleSet.hpp"

#include <cstdint>
#include <vector>

namespace hvi::sph {

struct NeighbourList {
    std::vector<int32_t> active;     ///< particles whose rates are evaluated this step
    std::vector<int64_t> offset;     ///< CSR offsets, size active.size() + 1
    std::vector<int32_t> neighbours; ///< extended indices (>= n: a mirror ghost)
    std::vector<int32_t> source;     ///< extended index -> particle index
    std::vector<double> sign;        ///< extended index -> +1 (real) or -1 (mirror)
    std::size_t ghostCount = 0;
    double cellSize = 0.0;

    std::size_t pairCount() const { return neighbours.size(); }
};

struct NeighbourSearchOptions {
    double kernelSupport = 2.0;  ///< support radius in units of h (kappa)
    bool axisymmetric = true;    ///< add mirror ghosts across r = 0
    bool skipDormant = true;     ///< search active cells only
};

/// True when particle i is disturbed (moving, pressurised or stressed). A dormant particle
/// with only dormant neighbours has exactly zero rates.
bool isAwake(const ParticleSet& particles, std::size_t i);

/// Rebuilds `list` for the current positions.
void buildNeighbourList(const ParticleSet& particles, const NeighbourSearchOptions& options,
                        NeighbourList& list);

} // namespace hvi::sph
