// The counting sort into cells (core/CellBins.hpp): every item with a cell is listed once,
// in its cell, in ascending order within the cell; items without a cell are left out.
#include "core/CellBins.hpp"

#include <gtest/gtest.h>
#include <vector>

using namespace hvi;

TEST(CellBins, ListsEachItemOnceInItsCellAscending) {
    const std::vector<long> cellOfItem = {2, 0, -1, 2, 1, 0, 2, -1};
    std::vector<int64_t> start;
    std::vector<int32_t> items;
    binByCell(
        cellOfItem.size(), 4, [&](std::size_t i) { return cellOfItem[i]; }, start, items);
    EXPECT_EQ(start, (std::vector<int64_t>{0, 2, 3, 6, 6}));
    EXPECT_EQ(items, (std::vector<int32_t>{1, 5, 4, 0, 3, 6}));
}

TEST(CellBins, EmptyAndInt32Offsets) {
    std::vector<int32_t> start, items;
    binByCell(
        0, 3, [](std::size_t) { return 0; }, start, items);
    EXPECT_EQ(start, (std::vector<int32_t>{0, 0, 0, 0}));
    EXPECT_TRUE(items.empty());
}
