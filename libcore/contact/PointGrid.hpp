// A uniform grid over points (FE segment midpoints or particles), the items of each cell
// listed together (CSR). Contact finds its candidate pairs with it (contact/ContactSearch):
// a query visits the 3 x 3 cells around a point, in cell order, so the candidates come in
// an order that depends on the positions only, not on the thread count.
//
// Units: mm.
#pragma once

#include "core/CellBins.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace hvi::contact {

/// A uniform grid over points (segment midpoints or particles), CSR by cell.
struct PointGrid {
    double z0 = 0.0, r0 = 0.0, cell = 1.0;
    long nz = 0, nr = 0;
    std::vector<int32_t> start, items;

    long cellZ(double z) const { return static_cast<long>(std::floor((z - z0) / cell)); }
    long cellR(double r) const { return static_cast<long>(std::floor((r - r0) / cell)); }

    template <class GetZ, class GetR>
    void build(std::size_t n, GetZ getZ, GetR getR, double cellSize) {
        cell = cellSize;
        double zLo = std::numeric_limits<double>::infinity(), zHi = -zLo, rLo = zLo, rHi = -zLo;
        for (std::size_t i = 0; i < n; ++i) {
            zLo = std::min(zLo, getZ(i));
            zHi = std::max(zHi, getZ(i));
            rLo = std::min(rLo, getR(i));
            rHi = std::max(rHi, getR(i));
        }
        if (n == 0) {
            nz = nr = 0;
            start.assign(1, 0);
            items.clear();
            return;
        }
        z0 = zLo - cell;
        r0 = rLo - cell;
        nz = cellZ(zHi) + 2;
        nr = cellR(rHi) + 2;
        binByCell(
            n, static_cast<std::size_t>(nz * nr),
            [&](std::size_t i) { return cellZ(getZ(i)) * nr + cellR(getR(i)); }, start, items);
    }

    /// Calls f(item) for the items in the 3 x 3 cells around (z, r), in cell order.
    template <class F>
    void forNear(double z, double r, F&& f) const {
        const long cz = cellZ(z), cr = cellR(r);
        for (long iz = std::max(cz - 1, 0L); iz <= std::min(cz + 1, nz - 1); ++iz) {
            for (long ir = std::max(cr - 1, 0L); ir <= std::min(cr + 1, nr - 1); ++ir) {
                const auto c = static_cast<std::size_t>(iz * nr + ir);
                for (int32_t k = start[c]; k < start[c + 1]; ++k) {
                    f(items[static_cast<std::size_t>(k)]);
                }
            }
        }
    }
};

} // namespace hvi::contact
