// Cell-list neighbour search in the (z, r) plane, O(N), with mirror ghosts across the axis,
// the "compute only what the scene needs" rule, and Verlet-list reuse between steps.
//
// A build bins the alive particles into square cells and lists, for every particle near the
// disturbed region, the particles within its pair support plus a skin:
// |x_i - x_j| < kappa (h_i + h_j)/2 + skin (the Verlet list: L. Verlet, Phys. Rev. 159 (1967)
// 98). The listed particles are those in the cells near an awake particle (moving, or
// carrying pressure or stress): the awake cells dilated by a guard band, then by the longest
// listed pair. Each step evaluates only the *active* particles: those in cells within one
// listed reach of a particle awake now. A particle outside them is at rest in its reference
// state with all its neighbours also at rest and unstressed, so its rates are exactly zero
// and skipping it changes nothing (tests check this bitwise).
//
// Reuse (updateNeighbourList): the lists stay valid while no pair can have come within its
// support unlisted. With d_i the displacement since the build and c any common translation
// along z, a pair distance shrinks by at most |d_i - d_j| <= |d_i - c| + |d_j - c|, and
// supports grow by kappa/2 (dh_i + dh_j); so the lists are kept while u_i + u_j <= skin for
// every pair, u = |d - c| + kappa/2 max(0, h - h_build). This is checked with the two largest
// u (c = the mid-range of the axial displacements, which halves the bound for a projectile
// moving as a block), and with twice the largest u of a particle that has a mirror (its own
// ghost is a pair; a translation along z leaves mirror images' displacements unchanged). An
// awake particle outside the guard band, a deletion or a change in the particle count also
// forces a rebuild. A particle that is not evaluated cannot wake (its rates are zero), so the
// active particles always have complete lists.
//
// Exactness: the pair loop keeps only pairs inside the support (the listed extras are
// skipped), and each particle's neighbours are listed in ascending extended index (real
// particles by index, then ghosts by the particle they mirror), an order that does not depend
// on when the list was built, on the cells, on the skin or on the thread count. The sums are
// therefore a function of the state alone: results are bitwise identical with and without
// dormant skipping and for 1 and N threads.
//
// Axisymmetric mode: particles within one listed reach of the axis get a mirror image at
// (z, -r) (a reflecting boundary: Spheral's AxisBoundaryRZ does the same), so kernel sums
// near the axis are not truncated. Ghosts are addressed as indices >= n with `source[j]` the
// particle they mirror and `sign[j] = -1` (r, v_r and S_rz change sign).
#pragma once

#include "sph/ParticleSet.hpp"

#include <cstdint>
#include <vector>

namespace hvi::sph {

struct NeighbourSearchOptions {
    double kernelSupport = 2.0;  ///< support radius in units of h (kappa)
    bool axisymmetric = true;    ///< add mirror ghosts across r = 0
    bool skipDormant = true;     ///< search active cells only
    /// Verlet skin in units of the median smoothing length. 0: exact lists, rebuilt on every
    /// update. Larger skins rebuild less often but list more candidate pairs; 0.3 keeps the
    /// listed reach (2.3 h = 3.0 spacings at the default h = 1.3 spacings) inside the next
    /// lattice shell (sqrt(10) spacings): measured best on the benchmark case.
    double skinFactor = 0.3;
    /// Guard band around the awake cells, in cells: how far the disturbance may spread before
    /// the lists are rebuilt. (Round-off-sized disturbances spread by about one support per
    /// step, so the band must be several cells wide for a list to live several steps.)
    int guardCells = 8;
};

/// Bookkeeping of the last build, for updateNeighbourList's reuse test.
struct NeighbourListBuildState {
    std::vector<double> z, r, h;   ///< positions and smoothing lengths at the build
    std::vector<uint8_t> alive;    ///< alive flags at the build
    std::vector<uint8_t> guarded;  ///< 1: may wake without a rebuild (inside the guard band)
    std::vector<uint8_t> mirrored; ///< 1: has a ghost in the list
    std::vector<int64_t> cell;     ///< cell of each alive particle at the build
    int64_t nz = 0, nr = 0;        ///< cell grid
    int64_t reachCells = 0;        ///< cells spanned by the longest listed pair
    NeighbourSearchOptions options; ///< the options of the build
    double skin = 0.0;             ///< [mm]
    bool valid = false;
    long builds = 0, reuses = 0;   ///< counters (diagnostics and tests)
    /// Each thread's rows during a build: scratch, kept between builds for its capacity.
    std::vector<std::vector<int32_t>> threadRows;
};

struct NeighbourList {
    std::vector<int32_t> active;     ///< particles whose rates are evaluated this step
    std::vector<int32_t> row;        ///< row[a]: the neighbour row of active[a]
    std::vector<int32_t> listed;     ///< particles with a neighbour row (ascending)
    std::vector<int64_t> offset;     ///< CSR offsets of the rows, size listed.size() + 1
    std::vector<int32_t> neighbours; ///< extended indices (>= n: a mirror ghost), ascending
    std::vector<int32_t> source;     ///< extended index -> particle index
    std::vector<double> sign;        ///< extended index -> +1 (real) or -1 (mirror)
    std::size_t ghostCount = 0;
    double cellSize = 0.0;
    double skin = 0.0;               ///< listed pairs reach kappa h_ij + skin [mm]
    NeighbourListBuildState build;

    /// Listed candidate pairs of the evaluated particles (those within the support are a
    /// subset).
    std::size_t pairCount() const {
        std::size_t pairs = 0;
        for (const int32_t rw : row) {
            pairs += static_cast<std::size_t>(offset[rw + 1] - offset[rw]);
        }
        return pairs;
    }
};

/// True when particle i is disturbed (moving, pressurised or stressed). A dormant particle
/// with only dormant neighbours has exactly zero rates.
bool isAwake(const ParticleSet& particles, std::size_t i);

/// Rebuilds `list` for the current state.
void buildNeighbourList(const ParticleSet& particles, const NeighbourSearchOptions& options,
                        NeighbourList& list);

/// Keeps `list` if it is still valid for the current state (see above), otherwise rebuilds
/// it. Returns true when it rebuilt.
bool updateNeighbourList(const ParticleSet& particles, const NeighbourSearchOptions& options,
                         NeighbourList& list);

} // namespace hvi::sph
