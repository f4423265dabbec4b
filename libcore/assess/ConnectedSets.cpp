#include "assess/ConnectedSets.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

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

std::vector<std::size_t> connectedSets(const std::vector<double>& z, const std::vector<double>& r,
                                       double link, const std::vector<std::uint8_t>& strong,
                                       double strongLink) {
    if (z.size() != r.size() || !(link > 0.0) || (!strong.empty() && strong.size() != z.size())) {
        throw std::invalid_argument(
            "connectedSets: z, r and strong differ in length, or link <= 0");
    }
    const double far = strong.empty() ? link : std::max(link, strongLink);
    const std::size_t n = z.size();
    UnionFind sets(n);
    std::unordered_map<std::int64_t, std::vector<std::size_t>> grid;
    auto cellOf = [&](double x) { return static_cast<std::int64_t>(std::floor(x / far)); };
    for (std::size_t k = 0; k < n; ++k) {
        grid[cellKey(cellOf(z[k]), cellOf(r[k]))].push_back(k);
    }
    const double tolerance = 1 + 1e-9; // lattice neighbours exactly `link` apart link up
    for (std::size_t k = 0; k < n; ++k) {
        const auto cz = cellOf(z[k]), cr = cellOf(r[k]);
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
            for (std::int64_t dr = -1; dr <= 1; ++dr) {
                const auto it = grid.find(cellKey(cz + dz, cr + dr));
                if (it == grid.end()) {
                    continue;
                }
                for (std::size_t j : it->second) {
                    const double reach = (!strong.empty() && strong[j] && strong[k]) ? far : link;
                    if (j > k && std::hypot(z[j] - z[k], r[j] - r[k]) <= reach * tolerance) {
                        sets.unite(j, k);
                    }
                }
            }
        }
    }
    std::vector<std::size_t> labels(n);
    for (std::size_t k = 0; k < n; ++k) {
        labels[k] = sets.find(k);
    }
    return labels;
}

} // namespace hvi::assess
