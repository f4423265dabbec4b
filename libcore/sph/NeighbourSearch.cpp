#include "sph/NeighbourSearch.hpp"

#include "core/CellBins.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <omp.h>
#include <utility>

namespace hvi::sph {

namespace {

/// Marks every cell within `radius` cells (Chebyshev distance) of a marked cell.
std::vector<uint8_t> dilate(const std::vector<uint8_t>& in, int64_t nz, int64_t nr,
                            int64_t radius) {
    if (radius <= 0) {
        return in;
    }
    // Separable: along r, then along z.
    std::vector<uint8_t> alongR(in.size(), 0);
    for (int64_t iz = 0; iz < nz; ++iz) {
        for (int64_t ir = 0; ir < nr; ++ir) {
            if (!in[iz * nr + ir]) {
                continue;
            }
            for (int64_t jr = std::max<int64_t>(ir - radius, 0);
                 jr <= std::min(ir + radius, nr - 1); ++jr) {
                alongR[iz * nr + jr] = 1;
            }
        }
    }
    std::vector<uint8_t> out(in.size(), 0);
    for (int64_t iz = 0; iz < nz; ++iz) {
        for (int64_t ir = 0; ir < nr; ++ir) {
            if (!alongR[iz * nr + ir]) {
                continue;
            }
            for (int64_t jz = std::max<int64_t>(iz - radius, 0);
                 jz <= std::min(iz + radius, nz - 1); ++jz) {
                out[jz * nr + ir] = 1;
            }
        }
    }
    return out;
}

bool sameOptions(const NeighbourSearchOptions& a, const NeighbourSearchOptions& b) {
    return a.kernelSupport == b.kernelSupport && a.axisymmetric == b.axisymmetric &&
           a.skipDormant == b.skipDormant && a.skinFactor == b.skinFactor &&
           a.guardCells == b.guardCells;
}

/// 1 for the particles that are awake (every alive one when dormant skipping is off).
std::vector<uint8_t> awakeFlags(const ParticleSet& ps, const NeighbourSearchOptions& options) {
    const std::size_t n = ps.size();
    std::vector<uint8_t> awake(n, 0);
#pragma omp parallel for schedule(static) if (n > kParallelMinItems)
    for (std::size_t i = 0; i < n; ++i) {
        awake[i] = ps.alive[i] && (!options.skipDormant || isAwake(ps, i)) ? 1 : 0;
    }
    return awake;
}

/// True while no pair can have entered the support unlisted and no particle outside the
/// guard band has woken (NeighbourSearch.hpp gives the argument).
bool stillValid(const ParticleSet& ps, const NeighbourSearchOptions& options,
                const NeighbourList& list, const std::vector<uint8_t>& awake) {
    const auto& st = list.build;
    const std::size_t n = ps.size();
    if (!st.valid || st.z.size() != n || !sameOptions(st.options, options) ||
        st.alive != ps.alive) {
        return false;
    }
    // Common axial translation c: the mid-range of the axial displacements.
    double dzMin = 0.0, dzMax = 0.0;
    bool wokeOutside = false;
    // min, max and "or" are exact and order-independent: any thread count gives the same.
#pragma omp parallel for schedule(static) if (n > kParallelMinItems) reduction(min                 \
                                                                               : dzMin)            \
    reduction(max                                                                                  \
              : dzMax) reduction(||                                                                \
                                 : wokeOutside)
    for (std::size_t i = 0; i < n; ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        const double dz = ps.z[i] - st.z[i];
        dzMin = std::min(dzMin, dz);
        dzMax = std::max(dzMax, dz);
        wokeOutside = wokeOutside || (awake[i] && !st.guarded[i]);
    }
    if (wokeOutside) {
        return false;
    }
    const double c = 0.5 * (dzMin + dzMax);
    const double halfKappa = 0.5 * options.kernelSupport;
    // Largest and second largest u over all particles; largest over mirrored ones. Per
    // thread, then merged: the two largest of a set do not depend on how it was split.
    double u1 = 0.0, u2 = 0.0, uMirror = 0.0;
    auto keepTopTwo = [](double u, double& first, double& second) {
        if (u > first) {
            second = first;
            first = u;
        } else if (u > second) {
            second = u;
        }
    };
#pragma omp parallel if (n > kParallelMinItems)
    {
        double l1 = 0.0, l2 = 0.0, lm = 0.0;
#pragma omp for schedule(static) nowait
        for (std::size_t i = 0; i < n; ++i) {
            if (!ps.alive[i]) {
                continue;
            }
            const double dz = ps.z[i] - st.z[i] - c, dr = ps.r[i] - st.r[i];
            double u = std::sqrt(dz * dz + dr * dr) + halfKappa * std::max(0.0, ps.h[i] - st.h[i]);
            if (std::isnan(u)) {
                u = std::numeric_limits<double>::infinity(); // a broken state: rebuild
            }
            keepTopTwo(u, l1, l2);
            if (st.mirrored[i]) {
                lm = std::max(lm, u);
            }
        }
#pragma omp critical(hviVerletTopTwo)
        {
            keepTopTwo(l1, u1, u2);
            keepTopTwo(l2, u1, u2);
            uMirror = std::max(uMirror, lm);
        }
    }
    // A hair under the skin, so rounding in the distances above cannot admit a pair the
    // build did not list.
    const double budget = st.skin * (1.0 - 1e-9);
    return u1 + u2 <= budget && 2.0 * uMirror <= budget;
}

/// The particles to evaluate now: those in the build cells within one listed reach of the
/// build cell of a particle awake now (see NeighbourSearch.hpp), with their rows.
void selectActive(const ParticleSet& ps, NeighbourList& list, const std::vector<uint8_t>& awake) {
    const auto& st = list.build;
    list.active.clear();
    list.row.clear();
    const std::size_t rows = list.listed.size();
    if (!st.options.skipDormant) {
        list.active = list.listed;
        list.row.resize(rows);
        for (std::size_t k = 0; k < rows; ++k) {
            list.row[k] = static_cast<int32_t>(k);
        }
        return;
    }
    std::vector<uint8_t> hot(static_cast<std::size_t>(st.nz * st.nr), 0);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (awake[i] && st.cell[i] >= 0) {
            hot[st.cell[i]] = 1;
        }
    }
    hot = dilate(hot, st.nz, st.nr, st.reachCells);
    compactIndices(
        rows, [&](std::size_t k) { return hot[st.cell[list.listed[k]]] != 0; }, list.row);
    list.active.resize(list.row.size());
    parallelFor(list.row.size(), [&](std::size_t a) { list.active[a] = list.listed[list.row[a]]; });
}

void build(const ParticleSet& ps, const NeighbourSearchOptions& options, NeighbourList& list,
           const std::vector<uint8_t>& awake);

} // namespace

bool isAwake(const ParticleSet& ps, std::size_t i) {
    if (ps.vz[i] != 0.0 || ps.vr[i] != 0.0 || ps.p[i] != 0.0) {
        return true;
    }
    if (ps.hasStrength() && (ps.szz[i] != 0.0 || ps.srr[i] != 0.0 || ps.srz[i] != 0.0)) {
        return true;
    }
    return false;
}

bool updateNeighbourList(const ParticleSet& ps, const NeighbourSearchOptions& options,
                         NeighbourList& list) {
    const std::vector<uint8_t> awake = awakeFlags(ps, options);
    const bool rebuild = !stillValid(ps, options, list, awake);
    if (rebuild) {
        build(ps, options, list, awake);
    } else {
        ++list.build.reuses;
    }
    selectActive(ps, list, awake);
    return rebuild;
}

void buildNeighbourList(const ParticleSet& ps, const NeighbourSearchOptions& options,
                        NeighbourList& list) {
    const std::vector<uint8_t> awake = awakeFlags(ps, options);
    build(ps, options, list, awake);
    selectActive(ps, list, awake);
}

namespace {

/// The alive particles' extent and their largest smoothing length.
struct Extent {
    double hMax = 0.0;
    double zMin = 1e300, zMax = -1e300, rMax = -1e300;
};

Extent aliveExtent(const ParticleSet& ps) {
    Extent e;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        e.hMax = std::max(e.hMax, ps.h[i]);
        e.zMin = std::min(e.zMin, ps.z[i]);
        e.zMax = std::max(e.zMax, ps.z[i]);
        e.rMax = std::max(e.rMax, ps.r[i]);
    }
    return e;
}

double medianAliveH(const ParticleSet& ps) {
    std::vector<double> hAlive;
    hAlive.reserve(ps.size());
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.alive[i]) {
            hAlive.push_back(ps.h[i]);
        }
    }
    std::nth_element(hAlive.begin(),
                     hAlive.begin() + static_cast<std::ptrdiff_t>(hAlive.size() / 2), hAlive.end());
    return hAlive[hAlive.size() / 2];
}

/// A build starts from the particles' current state and an empty list whose extended
/// indices are the particles themselves.
void startBuild(const ParticleSet& ps, const NeighbourSearchOptions& options, NeighbourList& list) {
    const std::size_t n = ps.size();
    list.listed.clear();
    list.offset.assign(1, 0); // the rows (buildRows resizes `neighbours` in place)
    auto& st = list.build;
    st.z = ps.z;
    st.r = ps.r;
    st.h = ps.h;
    st.alive = ps.alive;
    st.guarded.assign(n, 0);
    st.mirrored.assign(n, 0);
    st.cell.assign(n, -1);
    st.nz = st.nr = st.reachCells = 0;
    st.options = options;
    st.skin = 0.0;
    st.valid = true;
    ++st.builds;
    list.skin = 0.0;
    list.source.resize(n);
    list.sign.assign(n, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
        list.source[i] = static_cast<int32_t>(i);
    }
    list.ghostCount = 0;
}

/// Mirror ghosts of the particles that can come within one support of the axis before the
/// next build (extended indices n...).
void addMirrorGhosts(const ParticleSet& ps, double listedReach, NeighbourList& list) {
    const std::size_t n = ps.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (ps.alive[i] && ps.r[i] < listedReach) {
            list.source.push_back(static_cast<int32_t>(i));
            list.sign.push_back(-1.0);
            list.build.mirrored[i] = 1;
        }
    }
    list.ghostCount = list.source.size() - n;
}

/// The cell grid of a build over the extended particles (ghosts at -r), CSR by cell, with
/// each cell's largest h so a search can skip cells no pair support reaches.
struct BuildGrid {
    double zMin = 0.0, rLow = 0.0, cell = 0.0;
    int64_t nz = 0, nr = 0;
    std::vector<int64_t> cellOfExt; ///< per extended index (-1: not alive)
    std::vector<int64_t> start;     ///< CSR offsets, nz * nr + 1
    std::vector<int32_t> members;   ///< extended indices, ascending per cell
    /// z, signed r and h of each member, in the members' order: a search streams through
    /// its cells' positions instead of gathering them through `source`.
    std::vector<double> memberZ, memberR, memberH;
    std::vector<double> hMax; ///< per cell

    int64_t cellCount() const { return nz * nr; }
    int64_t cellOf(double zz, double rr) const {
        auto iz = static_cast<int64_t>((zz - zMin) / cell);
        auto ir = static_cast<int64_t>((rr - rLow) / cell);
        iz = std::clamp<int64_t>(iz, 0, nz - 1);
        ir = std::clamp<int64_t>(ir, 0, nr - 1);
        return iz * nr + ir;
    }
};

/// Cells of kernelSupport h_median + skin over the extent, grown if the box would need too
/// many (a far-flung debris particle); the extended particles sorted into them (counting
/// sort, stable: ascending index per cell).
BuildGrid makeGrid(const ParticleSet& ps, const NeighbourSearchOptions& options,
                   const NeighbourList& list, const Extent& extent, double hMedian, double skin,
                   double listedReach) {
    BuildGrid g;
    g.zMin = extent.zMin;
    g.rLow = -listedReach;
    if (!options.axisymmetric) {
        g.rLow = 1e300;
        for (std::size_t i = 0; i < ps.size(); ++i) {
            if (ps.alive[i]) {
                g.rLow = std::min(g.rLow, ps.r[i]);
            }
        }
    }
    double cell = options.kernelSupport * hMedian + skin;
    const double spanZ = extent.zMax - extent.zMin;
    const double spanR = extent.rMax - g.rLow;
    constexpr double kMaxCells = 4.0e6;
    while ((spanZ / cell + 1.0) * (spanR / cell + 1.0) > kMaxCells) {
        cell *= 1.5;
    }
    g.cell = cell;
    g.nz = static_cast<int64_t>(spanZ / cell) + 1;
    g.nr = static_cast<int64_t>(spanR / cell) + 1;
    const int64_t cellCount = g.cellCount();
    const std::size_t nExt = list.source.size();
    g.cellOfExt.assign(nExt, -1);
    for (std::size_t j = 0; j < nExt; ++j) {
        const int32_t s = list.source[j];
        if (ps.alive[s]) {
            g.cellOfExt[j] = g.cellOf(ps.z[s], list.sign[j] * ps.r[s]);
        }
    }
    binByCell(
        nExt, static_cast<std::size_t>(cellCount), [&](std::size_t j) { return g.cellOfExt[j]; },
        g.start, g.members);
    g.memberZ.resize(g.members.size());
    g.memberR.resize(g.members.size());
    g.memberH.resize(g.members.size());
    parallelFor(g.members.size(), [&](std::size_t k) {
        const int32_t j = g.members[k];
        const int32_t s = list.source[j];
        g.memberZ[k] = ps.z[s];
        g.memberR[k] = list.sign[j] * ps.r[s];
        g.memberH[k] = ps.h[s];
    });
    g.hMax.assign(static_cast<std::size_t>(cellCount), 0.0);
    for (std::size_t j = 0; j < nExt; ++j) {
        if (g.cellOfExt[j] >= 0) {
            const double hj = ps.h[list.source[j]];
            g.hMax[g.cellOfExt[j]] = std::max(g.hMax[g.cellOfExt[j]], hj);
        }
    }
    return g;
}

/// The listed particles: those in the awake cells dilated by the guard band (the disturbance
/// may spread that far before the next build), then by the longest listed pair; records
/// each particle's cell and guard flag in the build state.
void selectListed(const ParticleSet& ps, const NeighbourSearchOptions& options,
                  const std::vector<uint8_t>& awake, const BuildGrid& g, double listedReach,
                  NeighbourList& list) {
    const std::size_t n = ps.size();
    auto& st = list.build;
    const auto reachCells = static_cast<int64_t>(std::ceil(listedReach / g.cell));
    std::vector<uint8_t> awakeCell(static_cast<std::size_t>(g.cellCount()), 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (awake[i]) {
            awakeCell[g.cellOfExt[i]] = 1;
        }
    }
    const std::vector<uint8_t> guardCell =
        dilate(awakeCell, g.nz, g.nr, std::max(options.guardCells, 0));
    const std::vector<uint8_t> listedCell = dilate(guardCell, g.nz, g.nr, reachCells);
    st.nz = g.nz;
    st.nr = g.nr;
    st.reachCells = reachCells;
    for (std::size_t i = 0; i < n; ++i) {
        if (ps.alive[i]) {
            st.cell[i] = g.cellOfExt[i];
            st.guarded[i] = options.skipDormant ? guardCell[g.cellOfExt[i]] : 1;
            if (listedCell[g.cellOfExt[i]]) {
                list.listed.push_back(static_cast<int32_t>(i));
            }
        }
    }
}

/// Appends to `out` the extended particles within kappa h_ij + skin of particle i, ascending.
void findRow(const ParticleSet& ps, const BuildGrid& g, int32_t i, double kappa, double hMax,
             double skin, std::vector<int32_t>& out) {
    const double zi = ps.z[i], ri = ps.r[i], hi = ps.h[i];
    const int64_t c = g.cellOfExt[i];
    const int64_t iz = c / g.nr, ir = c % g.nr;
    const std::size_t before = out.size();
    const auto cellsOut =
        static_cast<int64_t>(std::ceil((kappa * 0.5 * (hi + hMax) + skin) / g.cell));
    for (int64_t jz = std::max<int64_t>(iz - cellsOut, 0); jz <= std::min(iz + cellsOut, g.nz - 1);
         ++jz) {
        const double zLoCell = g.zMin + static_cast<double>(jz) * g.cell;
        const double gapZ = std::max({0.0, zLoCell - zi, zi - (zLoCell + g.cell)});
        for (int64_t jr = std::max<int64_t>(ir - cellsOut, 0);
             jr <= std::min(ir + cellsOut, g.nr - 1); ++jr) {
            const int64_t cc = jz * g.nr + jr;
            const double rLoCell = g.rLow + static_cast<double>(jr) * g.cell;
            const double gapR = std::max({0.0, rLoCell - ri, ri - (rLoCell + g.cell)});
            const double cellReach = kappa * 0.5 * (hi + g.hMax[cc]) + skin;
            if (g.start[cc] == g.start[cc + 1] ||
                gapZ * gapZ + gapR * gapR >= cellReach * cellReach) {
                continue;
            }
            for (int64_t k = g.start[cc]; k < g.start[cc + 1]; ++k) {
                const int32_t j = g.members[k];
                if (j == i) {
                    continue;
                }
                const double dz = zi - g.memberZ[k];
                const double dr = ri - g.memberR[k];
                const double reach = kappa * 0.5 * (hi + g.memberH[k]) + skin;
                if (dz * dz + dr * dr < reach * reach) {
                    out.push_back(j);
                }
            }
        }
    }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(before), out.end());
}

/// Neighbour rows of the listed particles. Each thread takes a contiguous block of the listed
/// particles (static schedule) into its own scratch and then copies it to the block's place
/// in the joined list; each row is sorted, so it depends neither on the cells nor on the
/// thread count.
void buildRows(const ParticleSet& ps, const BuildGrid& g, double kappa, double hMax, double skin,
               NeighbourList& list) {
    const std::size_t listedCount = list.listed.size();
    auto& scratch = list.build.threadRows;
    scratch.resize(std::max<std::size_t>(scratch.size(), omp_get_max_threads()));
    list.offset.assign(listedCount + 1, 0);
#pragma omp parallel if (listedCount > kParallelMinHeavyItems)
    {
        // Private rows, handed over at the end: pushing into one shared vector would make the
        // threads write one cache line.
        std::vector<int32_t>& local = scratch[static_cast<std::size_t>(omp_get_thread_num())];
        local.clear();
        std::size_t first = listedCount; // this thread's first row
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < listedCount; ++a) {
            first = std::min(first, a);
            const std::size_t before = local.size();
            findRow(ps, g, list.listed[a], kappa, hMax, skin, local);
            list.offset[a + 1] = static_cast<int64_t>(local.size() - before);
        }
#pragma omp single
        {
            for (std::size_t a = 0; a < listedCount; ++a) {
                list.offset[a + 1] += list.offset[a];
            }
            list.neighbours.resize(static_cast<std::size_t>(list.offset[listedCount]));
        }
        if (!local.empty()) {
            std::copy(local.begin(), local.end(),
                      list.neighbours.begin() + static_cast<std::ptrdiff_t>(list.offset[first]));
        }
    }
}

void build(const ParticleSet& ps, const NeighbourSearchOptions& options, NeighbourList& list,
           const std::vector<uint8_t>& awake) {
    startBuild(ps, options, list);
    const Extent extent = aliveExtent(ps);
    if (extent.hMax <= 0.0) {
        list.neighbours.clear();
        return;
    }
    const double support = options.kernelSupport * extent.hMax;
    // Cell size from the median smoothing length, not the largest: where h varies (compressed
    // material next to an expanding debris cloud) cells sized by the largest h would hold
    // many times the particles a typical search needs. Particles reach further cells when
    // their pair support asks for it, and cells are skipped by their own largest h.
    const double hMedian = medianAliveH(ps);
    const double skin = std::max(0.0, options.skinFactor) * hMedian;
    list.build.skin = skin;
    list.skin = skin;
    const double listedReach = support + skin; // the longest listed pair
    if (options.axisymmetric) {
        addMirrorGhosts(ps, listedReach, list);
    }
    const BuildGrid grid = makeGrid(ps, options, list, extent, hMedian, skin, listedReach);
    selectListed(ps, options, awake, grid, listedReach, list);
    buildRows(ps, grid, options.kernelSupport, extent.hMax, skin, list);
}

} // namespace

} // namespace hvi::sph
