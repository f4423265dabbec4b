#include "contact/ContactSearch.hpp"

#include "contact/PointGrid.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <omp.h>

namespace hvi::contact {

namespace {

/// The segments by their midpoints.
PointGrid segmentGrid(const ContactPoints& pts, double cellSize) {
    const auto& nd = pts.nd;
    const auto& surface = pts.surface;
    auto midZ = [&](std::size_t s) {
        return 0.5 * (nd.z[static_cast<std::size_t>(surface.segA[s])] +
                      nd.z[static_cast<std::size_t>(surface.segB[s])]);
    };
    auto midR = [&](std::size_t s) {
        return 0.5 * (nd.r[static_cast<std::size_t>(surface.segA[s])] +
                      nd.r[static_cast<std::size_t>(surface.segB[s])]);
    };
    PointGrid grid;
    grid.build(surface.segmentCount(), midZ, midR, cellSize);
    return grid;
}

/// The alive particles within a cell of the box around the free nodes (into `near`), and
/// their grid; empty without free nodes.
PointGrid nearParticleGrid(const ContactPoints& pts, double cellSize, std::vector<int32_t>& near) {
    const auto& nd = pts.nd;
    const auto& ps = pts.ps;
    double zLo = std::numeric_limits<double>::infinity(), zHi = -zLo, rLo = zLo, rHi = -zLo;
    bool anyFree = false;
    for (const int32_t n : pts.slaveNodes) {
        const auto i = static_cast<std::size_t>(n);
        if (nd.elementCount[i] != 0) {
            continue;
        }
        anyFree = true;
        zLo = std::min(zLo, nd.z[i]);
        zHi = std::max(zHi, nd.z[i]);
        rLo = std::min(rLo, nd.r[i]);
        rHi = std::max(rHi, nd.r[i]);
    }
    PointGrid grid;
    if (!anyFree || pts.np == 0) {
        return grid;
    }
    for (std::size_t i = 0; i < pts.np; ++i) {
        if (ps.alive[i] && ps.z[i] > zLo - cellSize && ps.z[i] < zHi + cellSize &&
            ps.r[i] > rLo - cellSize && ps.r[i] < rHi + cellSize) {
            near.push_back(static_cast<int32_t>(i));
        }
    }
    grid.build(
        near.size(), [&](std::size_t k) { return ps.z[static_cast<std::size_t>(near[k])]; },
        [&](std::size_t k) { return ps.r[static_cast<std::size_t>(near[k])]; }, cellSize);
    return grid;
}

/// Notes an approach: the vote, and the target if the step may close the gap.
void noteApproach(SlaveContacts& out, int32_t target, double gap, double approach, double dt,
                  double cellSize) {
    if (approach > 0.0) {
        // The search reaches half a cell beyond any slave: no approach may outrun it.
        out.dt = std::min(out.dt, 0.5 * cellSize / approach);
        if (gap < approach * dt && out.count < kMaxContactsPerSlave) {
            out.target[static_cast<std::size_t>(out.count++)] = target;
        }
    }
}

} // namespace

std::vector<SlaveContacts> findCandidates(const ContactPoints& pts, double dt, double cellSize) {
    const auto& nd = pts.nd;
    const auto& half = pts.half;
    const std::size_t np = pts.np;
    const std::size_t slaveCount = pts.slaveCount();
    std::vector<SlaveContacts> found(slaveCount);
    const PointGrid segments = segmentGrid(pts, cellSize);
    std::vector<int32_t> nearParticles;
    const PointGrid particleGrid = nearParticleGrid(pts, cellSize, nearParticles);

#pragma omp parallel for schedule(dynamic, 256) if (slaveCount > kParallelMinItems)
    for (std::size_t k = 0; k < slaveCount; ++k) {
        if (k < np && !pts.ps.alive[k]) {
            continue;
        }
        const Slave sl = pts.slave(k);
        SlaveContacts& out = found[k];
        segments.forNear(*sl.z, *sl.r, [&](int32_t s) {
            const auto su = static_cast<std::size_t>(s);
            // A node never meets its own body's surface (its elements hold it).
            if (pts.surface.segBody[su] == sl.body && k >= np) {
                return;
            }
            const SegmentHit h = pts.segmentHit(*sl.z, *sl.r, su);
            if (!h.valid || h.gap <= -h.band) {
                return;
            }
            const auto a = static_cast<std::size_t>(pts.surface.segA[su]);
            const auto b = static_cast<std::size_t>(pts.surface.segB[su]);
            const double vmz = (1.0 - h.xi) * nd.vz[a] + h.xi * nd.vz[b];
            const double vmr = (1.0 - h.xi) * nd.vr[a] + h.xi * nd.vr[b];
            const double approach = -((*sl.vz - vmz) * h.nz + (*sl.vr - vmr) * h.nr);
            noteApproach(out, s, h.gap - sl.radius, approach, dt, cellSize);
        });
        if (sl.free && !nearParticles.empty()) {
            particleGrid.forNear(*sl.z, *sl.r, [&](int32_t kp) {
                const auto j =
                    static_cast<std::size_t>(nearParticles[static_cast<std::size_t>(kp)]);
                const SegmentHit h = pts.particleHit(sl, j);
                if (!h.valid) {
                    return;
                }
                const double approach =
                    -((*sl.vz - (*half.vz)[j]) * h.nz + (*sl.vr - (*half.vr)[j]) * h.nr);
                noteApproach(out, -1 - static_cast<int32_t>(j), h.gap, approach, dt, cellSize);
            });
        }
    }
    return found;
}

} // namespace hvi::contact
