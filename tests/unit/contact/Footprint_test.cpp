// A particle's footprint on an FE surface (libcore/contact/Footprint): each covered piece of
// a segment takes its share of the footprint's area (ring area in axisymmetry), split between
// the segment's nodes as the planar hat functions average over the piece. Checked against an
// independent midpoint-rule quadrature on a non-uniform chain, and for the properties the
// contact relies on: the shares sum to 1; in planar mode their first moment is the particle's
// foot (the impulse acts where the particle is); a uniform lattice of particles loads the
// nodes in proportion to their lumped masses, the axis node included (so a uniform blow moves
// a uniform surface uniformly); the footprint ends at the axis and at a corner; and a zero
// width gives the point shares of the node-to-segment contact.
#include "contact/Footprint.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using namespace hvi;

namespace {

/// A front face z = 0 from r = 0 outwards with the given node radii, segments A -> B along
/// +r (outward normal +z), then, if corner > 0, a face turning down to z = -corner at the
/// last node (normal +r).
struct Chain {
    std::vector<double> z, r;
    std::vector<int32_t> segA, segB, next, prev;

    Chain(const std::vector<double>& radii, double corner) {
        for (const double x : radii) {
            z.push_back(0.0);
            r.push_back(x);
        }
        if (corner > 0.0) {
            z.push_back(-corner);
            r.push_back(radii.back());
        }
        const auto n = static_cast<int32_t>(z.size());
        for (int32_t k = 0; k + 1 < n; ++k) {
            segA.push_back(k);
            segB.push_back(k + 1);
            next.push_back(k + 2 < n ? k + 1 : -1);
            prev.push_back(k - 1);
        }
    }
    contact::SurfaceChain view() const { return {segA, segB, next, prev, z, r}; }
};

double shareOf(const std::vector<contact::Share>& shares, int32_t index) {
    for (const auto& s : shares) {
        if (s.index == index) {
            return s.weight;
        }
    }
    return 0.0;
}

/// The reference, by the midpoint rule over [lo, hi]: each segment's covered area (weight r
/// or 1) and the mean of its hat parameter t over the covered part; the segment's area split
/// (1 - mean t, mean t) between its nodes, normalised by the total area.
std::vector<double> quadratureShares(const std::vector<double>& radii, double lo, double hi,
                                     bool axisymmetric) {
    const int steps = 200000;
    const std::size_t segments = radii.size() - 1;
    std::vector<double> area(segments, 0.0), sumT(segments, 0.0), count(segments, 0.0);
    double total = 0.0;
    for (int s = 0; s < steps; ++s) {
        const double x = lo + (hi - lo) * (s + 0.5) / steps;
        const double rho = axisymmetric ? x : 1.0;
        for (std::size_t k = 0; k < segments; ++k) {
            if (x >= radii[k] && x < radii[k + 1]) {
                area[k] += rho;
                sumT[k] += (x - radii[k]) / (radii[k + 1] - radii[k]);
                count[k] += 1.0;
            }
        }
        total += rho;
    }
    std::vector<double> w(radii.size(), 0.0);
    for (std::size_t k = 0; k < segments; ++k) {
        if (count[k] > 0.0) {
            const double meanT = sumT[k] / count[k];
            w[k] += area[k] * (1.0 - meanT) / total;
            w[k + 1] += area[k] * meanT / total;
        }
    }
    return w;
}

const std::vector<double> kRadii = {0.0, 0.04, 0.07, 0.12, 0.15, 0.2, 0.26, 0.3};

} // namespace

TEST(Footprint, ZeroWidthGivesThePointShares) {
    const Chain chain(kRadii, 0.0);
    std::vector<contact::Share> nodes, segments;
    contact::footprintShares(chain.view(), 2, 0.3, 0.0, true, nodes, segments);
    ASSERT_EQ(nodes.size(), 2u);
    EXPECT_DOUBLE_EQ(shareOf(nodes, 2), 0.7);
    EXPECT_DOUBLE_EQ(shareOf(nodes, 3), 0.3);
    ASSERT_EQ(segments.size(), 1u);
    EXPECT_DOUBLE_EQ(segments[0].weight, 1.0);
}

TEST(Footprint, SharesAreThePiecesAreasSplitByTheHatFunctions) {
    const Chain chain(kRadii, 0.0);
    // Centre r = 0.135 on segment 3 (0.12-0.15), half-width 0.07: covers 0.065-0.205,
    // five segments, six nodes.
    const double foot = 0.135, half = 0.07;
    for (const bool axisymmetric : {false, true}) {
        std::vector<contact::Share> nodes, segments;
        contact::footprintShares(chain.view(), 3, 0.5, half, axisymmetric, nodes, segments);
        const auto expected = quadratureShares(kRadii, foot - half, foot + half, axisymmetric);
        double sum = 0.0, moment = 0.0;
        for (std::size_t k = 0; k < kRadii.size(); ++k) {
            const double got = shareOf(nodes, static_cast<int32_t>(k));
            EXPECT_NEAR(got, expected[k], 1e-6)
                << "node " << k << (axisymmetric ? " (axisymmetric)" : " (planar)");
            sum += got;
            moment += got * kRadii[k];
        }
        EXPECT_NEAR(sum, 1.0, 1e-14);
        if (!axisymmetric) {
            // Planar: the shares are the hat functions' integrals, which reproduce r, so
            // their first moment is the particle's foot.
            EXPECT_NEAR(moment, foot, 1e-14);
        }
        double segmentSum = 0.0;
        for (const auto& s : segments) {
            segmentSum += s.weight;
        }
        EXPECT_NEAR(segmentSum, 1.0, 1e-14);
        EXPECT_EQ(segments.size(), 5u);
    }
}

TEST(Footprint, EndsAtTheAxis) {
    // A ring at r = 0.02 with half-width 0.05 lands on the disc r < 0.07: the shares are
    // those of a uniform load on that disc, nothing beyond it.
    const Chain chain(kRadii, 0.0);
    std::vector<contact::Share> nodes, segments;
    contact::footprintShares(chain.view(), 0, 0.5, 0.05, true, nodes, segments);
    const auto expected = quadratureShares(kRadii, 0.0, 0.07, true);
    for (std::size_t k = 0; k < kRadii.size(); ++k) {
        EXPECT_NEAR(shareOf(nodes, static_cast<int32_t>(k)), expected[k], 1e-6) << "node " << k;
    }
    EXPECT_EQ(shareOf(nodes, 3), 0.0);
    // In closed form the axis node takes half the first segment's ring area over the
    // disc's, (0.04^2 / 2) / 2 / (0.07^2 / 2) = 0.163.
    EXPECT_NEAR(shareOf(nodes, 0), 0.5 * (0.04 * 0.04) / (0.07 * 0.07), 1e-12);
}

TEST(Footprint, StopsAtACorner) {
    // The face turns down at r = 0.3 (node 7): a footprint reaching past it stays on the
    // front face and its shares are those of the front face alone.
    const Chain chain(kRadii, 0.1);
    std::vector<contact::Share> nodes, segments;
    contact::footprintShares(chain.view(), 6, 0.5, 0.06, true, nodes, segments);
    EXPECT_EQ(shareOf(nodes, 8), 0.0) << "the side face's lower node took a share";
    const auto expected = quadratureShares(kRadii, 0.22, 0.3, true);
    for (std::size_t k = 0; k < kRadii.size(); ++k) {
        EXPECT_NEAR(shareOf(nodes, static_cast<int32_t>(k)), expected[k], 1e-6) << "node " << k;
    }
}

TEST(Footprint, AUniformLatticeLoadsTheNodesAsTheirLumpedMasses) {
    // Particles at r = (j + 1/2) d, one per segment of a uniform face, each of ring mass
    // proportional to its radius and with the footprint of its lattice cell (half-width d/2).
    // Pressing uniformly, their summed loads on the nodes must be proportional to the nodes'
    // lumped masses (a quarter of each adjacent element's ring mass, so proportional to the
    // sum of the adjacent segments' mid radii), or a uniform blow would not move the surface
    // uniformly. The radius-weighted hat integrals give the axis node two thirds of that.
    const double d = 0.04;
    const int n = 8;
    std::vector<double> radii;
    for (int k = 0; k <= n; ++k) {
        radii.push_back(k * d);
    }
    const Chain chain(radii, 0.0);
    std::vector<double> load(radii.size(), 0.0), lumped(radii.size(), 0.0);
    std::vector<contact::Share> nodes, segments;
    for (int j = 0; j < n; ++j) {
        const double mass = (j + 0.5) * d;
        contact::footprintShares(chain.view(), j, 0.5, 0.5 * d, true, nodes, segments);
        for (const auto& share : nodes) {
            load[static_cast<std::size_t>(share.index)] += mass * share.weight;
        }
        lumped[static_cast<std::size_t>(j)] += 0.25 * mass;
        lumped[static_cast<std::size_t>(j) + 1] += 0.25 * mass;
    }
    const double ratio = load[1] / lumped[1];
    for (std::size_t k = 0; k < radii.size(); ++k) {
        EXPECT_NEAR(load[k] / lumped[k], ratio, 1e-12 * ratio) << "node " << k;
    }
}
