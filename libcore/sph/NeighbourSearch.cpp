#include "sph/NeighbourSearch.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <omp.h>

namespace hvi::sph {

bool isAwake(const ParticleSet& ps, std::size_t i) {
    if (ps.vz[i] != 0.0 || ps.vr[i] != 0.0 || ps.p[i] != 0.0) {
        return true;
    }
    if (ps.hasStrength() && (ps.szz[i] != 0.0 || ps.srr[i] != 0.0 || ps.srz[i] != 0.0)) {
        return true;
    }
    return false;
}

void buildNeighbourList(const ParticleSet& ps, const NeighbourSearchOptions& options,
                        NeighbourList& list) {
    const std::size_t n = ps.size();
    list.active.clear();
    list.neighbours.clear();
    list.offset.assign(1, 0);

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

    // Mirror ghosts of the particles within one support of the axis.
    if (options.axisymmetric) {
        for (std::size_t i = 0; i < n; ++i) {
            if (ps.alive[i] && ps.r[i] < support) {
                list.source.push_back(static_cast<int32_t>(i));
                list.sign.push_back(-1.0);
            }
        }
        list.ghostCount = list.source.size() - n;
    }
    const std::size_t nExt = list.source.size();
    const double rMin = options.axisymmetric ? -support : std::min(0.0, rMax) - support;
    double rLow = rMin;
    if (!options.axisymmetric) {
        rLow = 1e300;
        for (std::size_t i = 0; i < n; ++i) {
            if (ps.alive[i]) {
                rLow = std::min(rLow, ps.r[i]);
            }
        }
    }

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
    // Cell grid; grow the cells if the box would need too many (a far-flung debris particle).
    double cell = options.kernelSupport * hMedian;
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

    // Largest smoothing length per cell, for skipping cells no pair support reaches.
    std::vector<double> cellHMax(cellCount, 0.0);
    for (std::size_t j = 0; j < nExt; ++j) {
        if (cellOfExt[j] >= 0) {
            const double hj = ps.h[list.source[j]];
            cellHMax[cellOfExt[j]] = std::max(cellHMax[cellOfExt[j]], hj);
        }
    }
    // Active cells: those with an awake particle, dilated by the longest reach of a pair.
    const auto reachCells = static_cast<int64_t>(std::ceil(support / cell));
    std::vector<uint8_t> awakeCell(cellCount, options.skipDormant ? 0 : 1);
    if (options.skipDormant) {
        for (std::size_t i = 0; i < n; ++i) {
            if (ps.alive[i] && isAwake(ps, i)) {
                awakeCell[cellOfExt[i]] = 1;
            }
        }
    }
    std::vector<uint8_t> activeCell(cellCount, 0);
    for (int64_t iz = 0; iz < nz; ++iz) {
        for (int64_t ir = 0; ir < nr; ++ir) {
            if (!awakeCell[iz * nr + ir]) {
                continue;
            }
            for (int64_t dz = -reachCells; dz <= reachCells; ++dz) {
                for (int64_t dr = -reachCells; dr <= reachCells; ++dr) {
                    const int64_t jz = iz + dz, jr = ir + dr;
                    if (jz >= 0 && jz < nz && jr >= 0 && jr < nr) {
                        activeCell[jz * nr + jr] = 1;
                    }
                }
            }
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (ps.alive[i] && activeCell[cellOfExt[i]]) {
            list.active.push_back(static_cast<int32_t>(i));
        }
    }

    // Neighbour lists of the active particles. Each thread takes a contiguous block of the
    // active list (static schedule) and the blocks are joined in order: deterministic.
    const std::size_t activeCount = list.active.size();
    const int threads = omp_get_max_threads();
    std::vector<std::vector<int32_t>> threadNeighbours(threads);
    std::vector<int64_t> counts(activeCount, 0);
    const double kappa = options.kernelSupport;
#pragma omp parallel if (activeCount > kParallelMinItems)
    {
        auto& local = threadNeighbours[omp_get_thread_num()];
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < activeCount; ++a) {
            const int32_t i = list.active[a];
            const double zi = ps.z[i], ri = ps.r[i], hi = ps.h[i];
            const int64_t c = cellOfExt[i];
            const int64_t iz = c / nr, ir = c % nr;
            const std::size_t before = local.size();
            const auto cellsOut = static_cast<int64_t>(std::ceil(kappa * 0.5 * (hi + hMax) / cell));
            for (int64_t jz = std::max<int64_t>(iz - cellsOut, 0); jz <= std::min(iz + cellsOut, nz - 1); ++jz) {
                const double zLoCell = zMin + static_cast<double>(jz) * cell;
                const double gapZ = std::max({0.0, zLoCell - zi, zi - (zLoCell + cell)});
                for (int64_t jr = std::max<int64_t>(ir - cellsOut, 0); jr <= std::min(ir + cellsOut, nr - 1);
                     ++jr) {
                    const int64_t cc = jz * nr + jr;
                    const double rLoCell = rLow + static_cast<double>(jr) * cell;
                    const double gapR = std::max({0.0, rLoCell - ri, ri - (rLoCell + cell)});
                    const double cellReach = kappa * 0.5 * (hi + cellHMax[cc]);
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
                        const double reach = kappa * 0.5 * (hi + ps.h[s]);
                        if (dz * dz + dr * dr < reach * reach) {
                            local.push_back(j);
                        }
                    }
                }
            }
            counts[a] = static_cast<int64_t>(local.size() - before);
        }
    }
    list.offset.assign(activeCount + 1, 0);
    for (std::size_t a = 0; a < activeCount; ++a) {
        list.offset[a + 1] = list.offset[a] + counts[a];
    }
    list.neighbours.reserve(list.offset[activeCount]);
    for (const auto& local : threadNeighbours) {
        list.neighbours.insert(list.neighbours.end(), local.begin(), local.end());
    }
    // Neighbour order within a cell follows the extended index; cells are scanned in a fixed
    // order, so the list does not depend on the thread count.
}

} // namespace hvi::sph
