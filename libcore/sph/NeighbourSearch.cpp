#include "sph/NeighbourSearch.hpp"
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
#pragma omp parallel for schedule(static) if (n > kParallelMinItems) \
    reduction(min : dzMin) reduction(max : dzMax) reduction(|| : wokeOutside)
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
            double u = std::sqrt(dz * dz + dr * dr) +
                       halfKappa * std::max(0.0, ps.h[i] - st.h[i]);
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
    for (std::size_t k = 0; k < rows; ++k) {
        const int32_t i = list.listed[k];
        if (hot[st.cell[i]]) {
            list.active.push_back(i);
            list.row.push_back(static_cast<int32_t>(k));
        }
    }
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

void build(const ParticleSet& ps, const NeighbourSearchOptions& options, NeighbourList& list,
           const std::vector<uint8_t>& awake) {
    const std::size_t n = ps.size();
    list.listed.clear();
    list.neighbours.clear();
    list.offset.assign(1, 0);
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

    // Bounding box and cell size from the alive particles.
    double hMax = 0.0;
    double zMin = 1e300, zMax = -1e300, rMax = -1e300;
    for (std::size_t i = 0; i < n; ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        hMax = std::max(hMax, ps.h[i]);
        zMin = std::min(zMin, ps.z[i]);
        zMax = std::max(zMax, ps.z[i]);
        rMax = std::max(rMax, ps.r[i]);
    }
    list.source.resize(n);
    list.sign.assign(n, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
        list.source[i] = static_cast<int32_t>(i);
    }
    list.ghostCount = 0;
    if (hMax <= 0.0) {
        return;
    }
    const double support = options.kernelSupport * hMax;

    // Cell size from the median smoothing length, not the largest: where h varies (compressed
    // material next to an expanding debris cloud) cells sized by the largest h would hold
    // many times the particles a typical search needs. Particles reach further cells when
    // their pair support asks for it, and cells are skipped by their own largest h (below).
    std::vector<double> hAlive;
    hAlive.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (ps.alive[i]) {
            hAlive.push_back(ps.h[i]);
        }
    }
    std::nth_element(hAlive.begin(), hAlive.begin() + static_cast<std::ptrdiff_t>(hAlive.size() / 2),
                     hAlive.end());
    const double hMedian = hAlive[hAlive.size() / 2];
    const double skin = std::max(0.0, options.skinFactor) * hMedian;
    st.skin = skin;
    list.skin = skin;
    const double listedReach = support + skin; // the longest listed pair

    // Mirror ghosts of the particles that can come within one support of the axis before the
    // next build.
    if (options.axisymmetric) {
        for (std::size_t i = 0; i < n; ++i) {
            if (ps.alive[i] && ps.r[i] < listedReach) {
                list.source.push_back(static_cast<int32_t>(i));
                list.sign.push_back(-1.0);
                st.mirrored[i] = 1;
            }
        }
        list.ghostCount = list.source.size() - n;
    }
    const std::size_t nExt = list.source.size();
    double rLow = -listedReach;
    if (!options.axisymmetric) {
        rLow = 1e300;
        for (std::size_t i = 0; i < n; ++i) {
            if (ps.alive[i]) {
                rLow = std::min(rLow, ps.r[i]);
            }
        }
    }

    // Cell grid; grow the cells if the box would need too many (a far-flung debris particle).
    double cell = options.kernelSupport * hMedian + skin;
    const double spanZ = zMax - zMin;
    const double spanR = rMax - rLow;
    constexpr double kMaxCells = 4.0e6;
    while ((spanZ / cell + 1.0) * (spanR / cell + 1.0) > kMaxCells) {
        cell *= 1.5;
    }
    list.cellSize = cell;
    const auto nz = static_cast<int64_t>(spanZ / cell) + 1;
    const auto nr = static_cast<int64_t>(spanR / cell) + 1;
    const int64_t cellCount = nz * nr;
    auto cellOf = [&](double zz, double rr) {
        auto iz = static_cast<int64_t>((zz - zMin) / cell);
        auto ir = static_cast<int64_t>((rr - rLow) / cell);
        iz = std::clamp<int64_t>(iz, 0, nz - 1);
        ir = std::clamp<int64_t>(ir, 0, nr - 1);
        return iz * nr + ir;
    };

    // Counting sort of extended particles into cells (stable: ascending index per cell).
    std::vector<int64_t> cellOfExt(nExt, -1);
    std::vector<int64_t> cellStart(cellCount + 1, 0);
    for (std::size_t j = 0; j < nExt; ++j) {
        const int32_t s = list.source[j];
        if (!ps.alive[s]) {
            continue;
        }
        cellOfExt[j] = cellOf(ps.z[s], list.sign[j] * ps.r[s]);
        ++cellStart[cellOfExt[j] + 1];
    }
    for (int64_t c = 0; c < cellCount; ++c) {
        cellStart[c + 1] += cellStart[c];
    }
    std::vector<int32_t> cellMembers(cellStart[cellCount]);
    {
        std::vector<int64_t> fill(cellStart.begin(), cellStart.end() - 1);
        for (std::size_t j = 0; j < nExt; ++j) {
            if (cellOfExt[j] >= 0) {
                cellMembers[fill[cellOfExt[j]]++] = static_cast<int32_t>(j);
            }
        }
    }
    // Largest h per cell, so a search can skip cells no pair support reaches.
    std::vector<double> cellHMax(cellCount, 0.0);
    for (std::size_t j = 0; j < nExt; ++j) {
        if (cellOfExt[j] >= 0) {
            const double hj = ps.h[list.source[j]];
            cellHMax[cellOfExt[j]] = std::max(cellHMax[cellOfExt[j]], hj);
        }
    }
    // Listed cells: the awake cells, dilated by the guard band (the disturbance may spread
    // that far before the next build), then by the longest listed pair.
    const auto reachCells = static_cast<int64_t>(std::ceil(listedReach / cell));
    std::vector<uint8_t> awakeCell(cellCount, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (awake[i]) {
            awakeCell[cellOfExt[i]] = 1;
        }
    }
    const std::vector<uint8_t> guardCell =
        dilate(awakeCell, nz, nr, std::max(options.guardCells, 0));
    const std::vector<uint8_t> listedCell = dilate(guardCell, nz, nr, reachCells);
    st.nz = nz;
    st.nr = nr;
    st.reachCells = reachCells;
    for (std::size_t i = 0; i < n; ++i) {
        if (ps.alive[i]) {
            st.cell[i] = cellOfExt[i];
            st.guarded[i] = options.skipDormant ? guardCell[cellOfExt[i]] : 1;
            if (listedCell[cellOfExt[i]]) {
                list.listed.push_back(static_cast<int32_t>(i));
            }
        }
    }

    // Neighbour lists of the listed particles. Each thread takes a contiguous block of the
    // listed particles (static schedule) and the blocks are joined in order; each particle's list
    // is sorted, so it does not depend on the cells or the thread count.
    const std::size_t listedCount = list.listed.size();
    const int threads = omp_get_max_threads();
    std::vector<std::vector<int32_t>> threadNeighbours(threads);
    std::vector<int64_t> counts(listedCount, 0);
    const double kappa = options.kernelSupport;
#pragma omp parallel if (listedCount > kParallelMinHeavyItems)
    {
        // Filled privately and handed over at the end: pushing into the shared vector of
        // vectors would make the threads write one cache line (their vectors' headers).
        std::vector<int32_t> local;
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < listedCount; ++a) {
            const int32_t i = list.listed[a];
            const double zi = ps.z[i], ri = ps.r[i], hi = ps.h[i];
            const int64_t c = cellOfExt[i];
            const int64_t iz = c / nr, ir = c % nr;
            const std::size_t before = local.size();
            const auto cellsOut =
                static_cast<int64_t>(std::ceil((kappa * 0.5 * (hi + hMax) + skin) / cell));
            for (int64_t jz = std::max<int64_t>(iz - cellsOut, 0); jz <= std::min(iz + cellsOut, nz - 1); ++jz) {
                const double zLoCell = zMin + static_cast<double>(jz) * cell;
                const double gapZ = std::max({0.0, zLoCell - zi, zi - (zLoCell + cell)});
                for (int64_t jr = std::max<int64_t>(ir - cellsOut, 0); jr <= std::min(ir + cellsOut, nr - 1);
                     ++jr) {
                    const int64_t cc = jz * nr + jr;
                    const double rLoCell = rLow + static_cast<double>(jr) * cell;
                    const double gapR = std::max({0.0, rLoCell - ri, ri - (rLoCell + cell)});
                    const double cellReach = kappa * 0.5 * (hi + cellHMax[cc]) + skin;
                    if (cellStart[cc] == cellStart[cc + 1] ||
                        gapZ * gapZ + gapR * gapR >= cellReach * cellReach) {
                        continue;
                    }
                    for (int64_t k = cellStart[cc]; k < cellStart[cc + 1]; ++k) {
                        const int32_t j = cellMembers[k];
                        if (j == i) {
                            continue;
                        }
                        const int32_t s = list.source[j];
                        const double dz = zi - ps.z[s];
                        const double dr = ri - list.sign[j] * ps.r[s];
                        const double reach = kappa * 0.5 * (hi + ps.h[s]) + skin;
                        if (dz * dz + dr * dr < reach * reach) {
                            local.push_back(j);
                        }
                    }
                }
            }
            std::sort(local.begin() + static_cast<std::ptrdiff_t>(before), local.end());
            counts[a] = static_cast<int64_t>(local.size() - before);
        }
        threadNeighbours[omp_get_thread_num()] = std::move(local);
    }
    list.offset.assign(listedCount + 1, 0);
    for (std::size_t a = 0; a < listedCount; ++a) {
        list.offset[a + 1] = list.offset[a] + counts[a];
    }
    list.neighbours.reserve(list.offset[listedCount]);
    for (const auto& local : threadNeighbours) {
        list.neighbours.insert(list.neighbours.end(), local.begin(), local.end());
    }
}

} // namespace

} // namespace hvi::sph
