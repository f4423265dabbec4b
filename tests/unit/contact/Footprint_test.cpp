// A particle's footprint on an FE surface (libcore/contact/Footprint): the nodal shares are
// the shape functions' integrals over the footprint, weighted by the radius in axisymmetry.
// Checked against an independent midpoint-rule quadrature of the hat functions on a
// non-uniform chain, and against the properties the contact relies on: the shares sum to 1,
// their first moment is the footprint's centroid (so the impulse acts where the particle
// is, not beside it), the footprint ends at the axis and at a corner, and a zero width gives
// the point shares of the node-to-segment contact.
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

/// The reference: hat function of node k on the node radii, integrated by the midpoint rule
/// over [lo, hi] with weight r (or 1), normalised by the same rule's total.
std::vector<double> quadratureShares(const std::vector<double>& radii, double lo, double hi,
                                     bool axisymmetric) {
    const int steps = 200000;
    std::vector<double> w(radii.size(), 0.0);
    double total = 0.0;
    for (int s = 0; s < steps; ++s) {
        const double x = lo + (hi - lo) * (s + 0.5) / steps;
        const double rho = axisymmetric ? x : 1.0;
        for (std::size_t k = 0; k + 1 < radii.size(); ++k) {
            if (x >= radii[k] && x < radii[k + 1]) {
                const double t = (x - radii[k]) / (radii[k + 1] - radii[k]);
                w[k] += (1.0 - t) * rho;
                w[k + 1] += t * rho;
            }
        }
        total += rho;
    }
    for (auto& x : w) {
        x /= total;
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

TEST(Footprint, SharesAreTheWeightedShapeFunctionIntegrals) {
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
        // Linear shape functions reproduce r: the shares' first moment is the footprint's
        // centroid, the particle's foot in planar mode, its r-weighted centroid in RZ.
        const double lo = foot - half, hi = foot + half;
        const double centroid =
            axisymmetric ? (2.0 / 3.0) * (hi * hi * hi - lo * lo * lo) / (hi * hi - lo * lo) : foot;
        EXPECT_NEAR(moment, centroid, 1e-14);
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
    // In closed form the axis node takes (0.04^2 / 6) / (0.07^2 / 2) = 0.109; the point
    // contact gave it half the impulse.
    EXPECT_NEAR(shareOf(nodes, 0), (0.04 * 0.04 / 6.0) / (0.07 * 0.07 / 2.0), 1e-12);
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
