// The reused (Verlet) neighbour lists against a brute-force oracle: after any sequence of
// small moves, growths of h and wake-ups, every evaluated particle's pairs inside the support
// must be exactly the brute-force set, in ascending order, and every particle with an awake
// neighbour must be evaluated. A reuse that misses a pair, or keeps a list too long, fails.
#include "sph/NeighbourSearch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <random>
#include <vector>

using namespace hvi::sph;

namespace {

constexpr double kSpacing = 0.1;
constexpr double kH = 0.13;
constexpr double kKappa = 2.0;

/// A jittered lattice of nz x nr particles in the (z, r) half-plane, all at rest.
ParticleSet lattice(int nz, int nr, std::mt19937& rng) {
    std::uniform_real_distribution<double> jitter(-0.2 * kSpacing, 0.2 * kSpacing);
    ParticleSet ps;
    for (int iz = 0; iz < nz; ++iz) {
        for (int ir = 0; ir < nr; ++ir) {
            ps.add(iz * kSpacing + jitter(rng), (ir + 0.5) * kSpacing + 0.5 * jitter(rng), 0.0,
                   0.0, 1.0, kH, 2.7, 0.0, 0);
        }
    }
    return ps;
}

/// Brute force: the extended neighbours of i within the support, as (source, mirrored) keys
/// in ascending order (reals by index, then mirrors by index: the list's documented order).
std::vector<int64_t> bruteForce(const ParticleSet& ps, std::size_t i, bool axisymmetric) {
    std::vector<int64_t> reals, mirrors;
    for (std::size_t j = 0; j < ps.size(); ++j) {
        if (!ps.alive[j]) {
            continue;
        }
        const double reach = kKappa * 0.5 * (ps.h[i] + ps.h[j]);
        const double dz = ps.z[i] - ps.z[j];
        const double dr = ps.r[i] - ps.r[j];
        if (j != i && dz * dz + dr * dr < reach * reach) {
            reals.push_back(static_cast<int64_t>(j));
        }
        const double drm = ps.r[i] + ps.r[j];
        if (axisymmetric && dz * dz + drm * drm < reach * reach) {
            mirrors.push_back(static_cast<int64_t>(j));
        }
    }
    reals.insert(reals.end(), mirrors.begin(), mirrors.end());
    return reals;
}

/// The listed neighbours of active[a] inside the support, as the same keys.
std::vector<int64_t> listedInside(const ParticleSet& ps, const NeighbourList& list,
                                  std::size_t a) {
    const int32_t i = list.active[a];
    const int32_t row = list.row[a];
    std::vector<int64_t> out;
    std::vector<int64_t> mirrors;
    for (int64_t k = list.offset[row]; k < list.offset[row + 1]; ++k) {
        const int32_t j = list.neighbours[k];
        const int32_t s = list.source[j];
        const double reach = kKappa * 0.5 * (ps.h[i] + ps.h[s]);
        const double dz = ps.z[i] - ps.z[s];
        const double dr = ps.r[i] - list.sign[j] * ps.r[s];
        if (dz * dz + dr * dr < reach * reach) {
            (list.sign[j] > 0.0 ? out : mirrors).push_back(s);
            // Mirrors must come after every real neighbour.
            EXPECT_TRUE(list.sign[j] < 0.0 || mirrors.empty());
        }
    }
    out.insert(out.end(), mirrors.begin(), mirrors.end());
    return out;
}

/// Checks the list against the brute force: pair sets and order, and that every particle
/// that is awake or has an awake neighbour is evaluated.
void expectExact(const ParticleSet& ps, const NeighbourList& list, bool axisymmetric) {
    std::vector<uint8_t> evaluated(ps.size(), 0);
    for (std::size_t a = 0; a < list.active.size(); ++a) {
        const int32_t i = list.active[a];
        evaluated[i] = 1;
        ASSERT_EQ(listedInside(ps, list, a), bruteForce(ps, i, axisymmetric)) << "particle " << i;
    }
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i] || evaluated[i]) {
            continue;
        }
        EXPECT_FALSE(isAwake(ps, i)) << "awake particle " << i << " not evaluated";
        for (const int64_t j : bruteForce(ps, i, axisymmetric)) {
            EXPECT_FALSE(isAwake(ps, static_cast<std::size_t>(j)))
                << "particle " << i << " has the awake neighbour " << j << " but is skipped";
        }
    }
}

} // namespace

TEST(NeighbourSearch, ReusedListsMatchBruteForceAsParticlesMoveAndWake) {
    std::mt19937 rng(7);
    ParticleSet ps = lattice(40, 30, rng);
    // A disturbed patch near the axis: moving particles whose wake spreads.
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.z[i] < 0.5 && ps.r[i] < 0.5) {
            ps.vz[i] = 1.0;
        }
    }
    NeighbourSearchOptions options;
    options.axisymmetric = true;
    options.kernelSupport = kKappa;
    options.guardCells = 1;
    NeighbourList list;
    std::normal_distribution<double> step(0.0, 0.02 * kSpacing);
    int rebuilds = 0, reuses = 0;
    for (int s = 0; s < 60; ++s) {
        rebuilds += updateNeighbourList(ps, options, list) ? 1 : 0;
        reuses = static_cast<int>(list.build.reuses);
        expectExact(ps, list, true);
        if (::testing::Test::HasFailure()) {
            FAIL() << "at step " << s;
        }
        // Move the awake particles (a common drift along z plus noise), grow some h, and
        // wake the neighbours of awake particles (a disturbance spreading one support a step).
        std::vector<uint8_t> wake(ps.size(), 0);
        for (std::size_t i = 0; i < ps.size(); ++i) {
            if (isAwake(ps, i)) {
                for (const int64_t j : bruteForce(ps, i, true)) {
                    wake[static_cast<std::size_t>(j)] = 1;
                }
            }
        }
        for (std::size_t i = 0; i < ps.size(); ++i) {
            if (isAwake(ps, i)) {
                ps.z[i] += 0.01 * kSpacing + step(rng);
                ps.r[i] = std::max(0.01, ps.r[i] + step(rng));
                ps.h[i] *= 1.0 + 0.002 * static_cast<double>(i % 3);
            }
            if (wake[i]) {
                ps.p[i] = 1e-3;
            }
        }
    }
    // The scenario must exercise both paths.
    EXPECT_GT(rebuilds, 3);
    EXPECT_GT(reuses, 10);
}

TEST(NeighbourSearch, DeletionAndZeroSkinForceRebuilds) {
    std::mt19937 rng(11);
    ParticleSet ps = lattice(20, 20, rng);
    ps.vz[0] = 1.0;
    NeighbourSearchOptions options;
    NeighbourList list;
    EXPECT_TRUE(updateNeighbourList(ps, options, list));
    EXPECT_FALSE(updateNeighbourList(ps, options, list)); // nothing changed
    ps.alive[5] = 0;
    EXPECT_TRUE(updateNeighbourList(ps, options, list));
    expectExact(ps, list, true);
    options.skinFactor = 0.0;
    EXPECT_TRUE(updateNeighbourList(ps, options, list)); // options changed
    ps.z[0] += 1e-9;
    EXPECT_TRUE(updateNeighbourList(ps, options, list)); // no skin: any move rebuilds
    expectExact(ps, list, true);
}

TEST(NeighbourSearch, PlanarWithoutDormantSkippingListsEveryone) {
    std::mt19937 rng(3);
    ParticleSet ps = lattice(15, 25, rng);
    NeighbourSearchOptions options;
    options.axisymmetric = false;
    options.skipDormant = false;
    NeighbourList list;
    updateNeighbourList(ps, options, list);
    EXPECT_EQ(list.active.size(), ps.size());
    expectExact(ps, list, false);
}
