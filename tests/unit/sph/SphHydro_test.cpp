// The SPH time-step vote (SphHydro.cpp): a particle with neighbours inside its support votes
// the Courant limit h / (c + 1.2 (alpha c + beta mu_max)) (Monaghan 1992, ARA&A 30:543,
// with the artificial-viscosity signal speed); a particle with none exchanges no signal, so it
// votes only h / |v| (it must not cross its own support in a step), however high its sound
// speed.
#include "PlanarSph.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi::sph;

namespace {

constexpr double kH = 0.05;

/// Evaluates `ps` (planar) and returns the vote.
double voteOf(const ParticleSet& ps) {
    ParticleRates rates;
    return hvi::test::evaluatePlanar(ps, HydroOptions{}, rates).stableTimeStep();
}

ParticleSet particle(double z, double vz, double soundSpeed) {
    ParticleSet ps;
    ps.add(z, 1.0, vz, 0.0, 1e-3, kH, 2.7, 0.0, 0);
    ps.cs.back() = soundSpeed;
    return ps;
}

} // namespace

TEST(SphHydroVote, LoneParticleVotesItsDisplacementOnly) {
    // A shocked lone debris particle: sound speed 40 km/s, moving at 0.8 km/s.
    ParticleSet ps = particle(0.0, 0.8, 40.0);
    EXPECT_DOUBLE_EQ(voteOf(ps), kH / 0.8);
    // At rest it sets no limit at all.
    ps.vz[0] = 0.0;
    EXPECT_TRUE(std::isinf(voteOf(ps)));
}

TEST(SphHydroVote, ParticlesWithNeighboursVoteTheCourantLimit) {
    // Two particles at rest one smoothing length apart (inside the support of 2 h), c = 5:
    // no approach, so the signal speed is c (1 + 1.2 alpha), alpha = 1.
    ParticleSet ps = particle(0.0, 0.0, 5.0);
    ps.add(kH, 1.0, 0.0, 0.0, 1e-3, kH, 2.7, 0.0, 0);
    ps.cs.back() = 5.0;
    EXPECT_NEAR(voteOf(ps), kH / (5.0 * 2.2), 1e-15);
    // The lone particle's rule does not apply once it has a neighbour, however slow.
    ps.vz[0] = 0.8;
    EXPECT_LT(voteOf(ps), kH / 5.0);
}

// The pair counts the benchmark's pair throughput and flop rate are computed from
// (SphHydro::pairCounts): the pairs inside the support (h_ij = (h_i + h_j) / 2, support 2 h_ij,
// a particle not its own neighbour), counted here by brute force over a jittered lattice with
// varied smoothing lengths, and the computed ones, each particle's padded to the loop's four
// lanes.
TEST(SphHydroPairs, CountsTheSupportsPairsAndTheirPadding) {
    ParticleSet ps;
    for (int iz = 0; iz < 9; ++iz) {
        for (int ir = 0; ir < 9; ++ir) {
            const double jitter = 0.1 * kH * std::sin(1.7 * iz + 2.3 * ir);
            const double h = kH * (1.0 + 0.3 * std::cos(0.9 * iz - 1.1 * ir));
            ps.add(iz * 0.8 * kH + jitter, ir * 0.8 * kH - jitter, 0.0, 0.0, 1e-3, h, 2.7, 0.0, 0);
        }
    }
    std::size_t inside = 0, computed = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        std::size_t own = 0;
        for (std::size_t j = 0; j < ps.size(); ++j) {
            const double dz = ps.z[i] - ps.z[j], dr = ps.r[i] - ps.r[j];
            const double support = 2.0 * 0.5 * (ps.h[i] + ps.h[j]);
            own += (j != i && dz * dz + dr * dr < support * support) ? 1 : 0;
        }
        inside += own;
        computed += (own + 3) / 4 * 4;
    }
    ParticleRates rates;
    const SphHydro hydro = hvi::test::evaluatePlanar(ps, HydroOptions{}, rates);
    EXPECT_EQ(hydro.pairCounts().inside, inside);
    EXPECT_EQ(hydro.pairCounts().computed, computed);
    EXPECT_GT(computed, inside); // the lattice is irregular enough to need padding
}
