// The evolving set (solver/EvolvingSet.hpp): it only grows, stays sorted without repeats
// whatever order the newcomers come in, and clear/fill set it to none or all.
#include "solver/EvolvingSet.hpp"

#include <gtest/gtest.h>
#include <vector>

using namespace hvi;

TEST(EvolvingSet, IncludeKeepsItSortedWithoutRepeats) {
    solver::EvolvingSet set;
    set.clear(10);
    EXPECT_EQ(set.size(), 0u);
    const std::vector<int32_t> first = {7, 2, 7, 5};
    set.include(first);
    EXPECT_EQ(set.items(), (std::vector<int32_t>{2, 5, 7}));
    const std::vector<int32_t> second = {9, 0, 5, 3};
    set.include(second);
    EXPECT_EQ(set.items(), (std::vector<int32_t>{0, 2, 3, 5, 7, 9}));
    EXPECT_TRUE(set.contains(3));
    EXPECT_FALSE(set.contains(4));
}

TEST(EvolvingSet, ClearAndFill) {
    solver::EvolvingSet set;
    set.fill(4);
    EXPECT_EQ(set.items(), (std::vector<int32_t>{0, 1, 2, 3}));
    const std::vector<int32_t> again = {1, 3};
    set.include(again); // nothing new
    EXPECT_EQ(set.size(), 4u);
    set.clear(4);
    EXPECT_EQ(set.size(), 0u);
    EXPECT_FALSE(set.contains(1));
}
