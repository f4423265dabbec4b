#include "assess/FailurePath.hpp"

#include "assess/MaterialState.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace hvi::assess {

namespace {

struct UnionFind {
    std::vector<std::size_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    std::size_t find(std::size_t a) {
        while (parent[a] != a) {
            parent[a] = parent[parent[a]];
            a = parent[a];
        }
        return a;
    }
    void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

std::int64_t cellKey(std::int64_t ix, std::int64_t iy) {
    return ix * 4000037LL + iy; // a prime stride: distinct for |iy| < 2e6 cells
}

} // namespace

FailurePath failurePath(const MaterialItems& items, std::size_t b, const ShieldLayout& layout,
                        const Criteria& criteria) {
    const BodyLayout& body = layout.bodies[b];
    const bool acrossR = body.thinInR();
    const double lo = acrossR ? body.rMin : body.zFront;
    const double hi = acrossR ? body.rMax : body.zRear;
    const double s = body.spacing;
    const double link = criteria.linkSpacings * s;

    // Failed items of the body, at their reference positions.
    std::vector<double> pz, pr;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (belongsTo(items, i, b) && isFailed(items, i, layout, criteria)) {
            pz.push_back(items.z0[i]);
            pr.push_back(items.r0[i]);
        }
    }
    FailurePath result;
    result.failedItems = pz.size();
    if (pz.empty()) {
        return result;
    }
    const std::size_t n = pz.size();
    UnionFind sets(n);
    std::unordered_map<std::int64_t, std::vector<std::size_t>> grid;
    auto cellOf = [&](double x) { return static_cast<std::int64_t>(std::floor(x / link)); };
    for (std::size_t k = 0; k < n; ++k) {
        grid[cellKey(cellOf(pz[k]), cellOf(pr[k]))].push_back(k);
    }
    for (std::size_t k = 0; k < n; ++k) {
        const auto cz = cellOf(pz[k]), cr = cellOf(pr[k]);
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
            for (std::int64_t dr = -1; dr <= 1; ++dr) {
                const auto it = grid.find(cellKey(cz + dz, cr + dr));
                if (it == grid.end()) {
                    continue;
                }
                for (std::size_t j : it->second) {
                    if (j > k && std::hypot(pz[j] - pz[k], pr[j] - pr[k]) <= link * (1 + 1e-9)) {
                        sets.unite(j, k);
                    }
                }
            }
        }
    }
    // Roots touching each face.
    std::unordered_map<std::size_t, std::uint8_t> faces; // bit 1 front, bit 2 rear
    std::unordered_map<std::size_t, double> minR;
    for (std::size_t k = 0; k < n; ++k) {
        const double u = acrossR ? pr[k] : pz[k];
        const std::size_t root = sets.find(k);
        auto& f = faces[root];
        if (u <= lo + s) {
            f |= 1;
        }
        if (u >= hi - s) {
            f |= 2;
        }
        auto [it, inserted] = minR.emplace(root, pr[k]);
        if (!inserted) {
            it->second = std::min(it->second, pr[k]);
        }
    }
    double pathR = std::numeric_limits<double>::infinity();
    for (const auto& [root, f] : faces) {
        if (f == 3) {
            result.crosses = true;
            pathR = std::min(pathR, minR[root]);
        }
    }
    if (result.crosses) {
        result.pathRadiusMm = pathR;
    }
    return result;
}

} // namespace hvi::assess
