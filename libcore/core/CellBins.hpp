// Items binned into the cells of a grid by a counting sort, in CSR form: the items of cell c
// are items[start[c] .. start[c + 1]), in ascending item order (the sort is stable), so
// whatever visits a cell's items does so in an order that depends on the positions only. The
// SPH neighbour search (sph/NeighbourSearch.cpp) and contact's point grid
// (contact/PointGrid.hpp) bin with it; each keeps its own cell geometry (the search clamps far
// debris into its border cells, contact pads its box by a cell).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hvi {

/// `cellOf(i)`: item i's cell in [0, cellCount), or a negative value to leave it out. Called
/// twice per item.
template <class Offset, class CellOf>
void binByCell(std::size_t itemCount, std::size_t cellCount, CellOf&& cellOf,
               std::vector<Offset>& start, std::vector<int32_t>& items) {
    start.assign(cellCount + 1, 0);
    for (std::size_t i = 0; i < itemCount; ++i) {
        const auto c = cellOf(i);
        if (c >= 0) {
            ++start[static_cast<std::size_t>(c) + 1];
        }
    }
    for (std::size_t c = 0; c < cellCount; ++c) {
        start[c + 1] += start[c];
    }
    items.assign(static_cast<std::size_t>(start[cellCount]), 0);
    std::vector<Offset> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < itemCount; ++i) {
        const auto c = cellOf(i);
        if (c >= 0) {
            items[static_cast<std::size_t>(fill[static_cast<std::size_t>(c)]++)] =
                static_cast<int32_t>(i);
        }
    }
}

} // namespace hvi
