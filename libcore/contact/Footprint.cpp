#include "contact/Footprint.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::contact {

namespace {

/// A chain turning by more than this (cosine of the angle between segment normals) ends the
/// footprint: 45 degrees.
constexpr double kCornerCosine = 0.70710678118654752;
/// Segments walked each way at most (a guard for closed chains of tiny segments).
constexpr int kMaxSegmentsEachWay = 64;

struct Segment {
    double za, ra, zb, rb, length, nz, nr;
};

Segment segmentOf(const SurfaceChain& chain, int32_t s) {
    const auto a = static_cast<std::size_t>(chain.segA[static_cast<std::size_t>(s)]);
    const auto b = static_cast<std::size_t>(chain.segB[static_cast<std::size_t>(s)]);
    Segment g{chain.z[a], chain.r[a], chain.z[b], chain.r[b], 0.0, 0.0, 0.0};
    const double tz = g.zb - g.za, tr = g.rb - g.ra;
    g.length = std::sqrt(tz * tz + tr * tr);
    if (g.length > 0.0) {
        g.nz = tr / g.length; // outward: the element lies to the left of A -> B
        g.nr = -tz / g.length;
    }
    return g;
}

void addShare(std::vector<Share>& shares, int32_t index, double weight) {
    for (auto& s : shares) {
        if (s.index == index) {
            s.weight += weight;
            return;
        }
    }
    shares.push_back({index, weight});
}

} // namespace

void footprintShares(const SurfaceChain& chain, int32_t centre, double xi, double halfWidth,
                     bool axisymmetric, std::vector<Share>& nodes, std::vector<Share>& segments) {
    nodes.clear();
    segments.clear();
    const auto centreIndex = static_cast<std::size_t>(centre);
    const Segment c = segmentOf(chain, centre);
    auto pointShares = [&] {
        nodes.clear();
        segments.clear();
        nodes.push_back({chain.segA[centreIndex], 1.0 - xi});
        nodes.push_back({chain.segB[centreIndex], xi});
        segments.push_back({centre, 1.0});
    };
    if (!(halfWidth > 0.0) || !(c.length > 0.0)) {
        pointShares();
        return;
    }
    // The piece [t1, t2] of segment s (parameter along A -> B): its weight, the integral of
    // rho(t) = r_A + (r_B - r_A) t (or 1) over its arc length, split between A and B as the
    // planar shape functions N_A = 1 - t, N_B = t average over it.
    auto addPiece = [&](int32_t s, const Segment& g, double t1, double t2) {
        if (!(t2 > t1)) {
            return;
        }
        const double meanRho = axisymmetric ? g.ra + 0.5 * (g.rb - g.ra) * (t1 + t2) : 1.0;
        const double weight = g.length * (t2 - t1) * meanRho;
        const double meanT = 0.5 * (t1 + t2);
        const auto su = static_cast<std::size_t>(s);
        addShare(nodes, chain.segA[su], weight * (1.0 - meanT));
        addShare(nodes, chain.segB[su], weight * meanT);
        addShare(segments, s, weight);
    };
    // The centre segment's part, then the chain each way until the half-width is used up.
    const double reach = halfWidth / c.length;
    addPiece(centre, c, std::max(xi - reach, 0.0), std::min(xi + reach, 1.0));
    for (const int direction : {1, -1}) {
        double remaining = halfWidth - (direction > 0 ? 1.0 - xi : xi) * c.length;
        int32_t s = centre;
        for (int walked = 0; walked < kMaxSegmentsEachWay && remaining > 0.0; ++walked) {
            s = direction > 0 ? chain.next[static_cast<std::size_t>(s)]
                              : chain.prev[static_cast<std::size_t>(s)];
            if (s < 0 || s == centre) {
                break;
            }
            const Segment g = segmentOf(chain, s);
            if (!(g.length > 0.0) || g.nz * c.nz + g.nr * c.nr < kCornerCosine) {
                break;
            }
            const double part = std::min(remaining / g.length, 1.0);
            if (direction > 0) {
                addPiece(s, g, 0.0, part);
            } else {
                addPiece(s, g, 1.0 - part, 1.0);
            }
            remaining -= g.length;
        }
    }
    double total = 0.0;
    for (const auto& n : nodes) {
        total += n.weight;
    }
    if (!(total > 0.0)) {
        pointShares();
        return;
    }
    for (auto& n : nodes) {
        n.weight /= total;
    }
    for (auto& s : segments) {
        s.weight /= total;
    }
}

} // namespace hvi::contact
