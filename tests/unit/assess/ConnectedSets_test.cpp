// Connected sets in the (z, r) plane (assess/ConnectedSets.hpp): lattice neighbours link,
// a gap wider than the link separates, chains link transitively, and strong pairs link
// farther than the rest.
#include "assess/ConnectedSets.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

using hvi::assess::connectedSets;

TEST(ConnectedSets, TwoBlocksApartAreTwoSetsAndEachIsOne) {
    // Two 3x3 lattices (spacing 1) 2.5 apart; link 1.5 joins the 8 neighbours of a point.
    std::vector<double> z, r;
    for (double z0 : {0.0, 4.5}) {
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                z.push_back(z0 + i);
                r.push_back(j);
            }
        }
    }
    const auto label = connectedSets(z, r, 1.5);
    for (std::size_t k = 0; k < 9; ++k) {
        EXPECT_EQ(label[k], label[0]) << k;
        EXPECT_EQ(label[k + 9], label[9]) << k;
    }
    EXPECT_NE(label[0], label[9]);
}

TEST(ConnectedSets, AChainLinksItsEndsAndALinkIsInclusive) {
    // Points exactly one link apart along a diagonal line: one set end to end.
    std::vector<double> z, r;
    for (int k = 0; k < 20; ++k) {
        z.push_back(0.3 * k);
        r.push_back(0.4 * k); // steps of exactly 0.5
    }
    const auto label = connectedSets(z, r, 0.5);
    EXPECT_EQ(label.front(), label.back());
    const auto apart = connectedSets(z, r, 0.499);
    EXPECT_NE(apart.front(), apart[1]);
}

TEST(ConnectedSets, StrongPairsLinkFartherOnlyWhenBothAreStrong) {
    // Three points 2 apart: link 1.5, strong link 3. 0-1 both strong: linked; 1-2 one weak:
    // not.
    const std::vector<double> z{0.0, 2.0, 4.0}, r{0.0, 0.0, 0.0};
    const std::vector<std::uint8_t> strong{1, 1, 0};
    const auto label = connectedSets(z, r, 1.5, strong, 3.0);
    EXPECT_EQ(label[0], label[1]);
    EXPECT_NE(label[1], label[2]);
    const auto weak = connectedSets(z, r, 1.5);
    EXPECT_NE(weak[0], weak[1]);
}

TEST(ConnectedSets, BadArgumentsAreRefused) {
    EXPECT_THROW(connectedSets({0.0}, {0.0, 1.0}, 1.0), std::invalid_argument);
    EXPECT_THROW(connectedSets({0.0}, {0.0}, 0.0), std::invalid_argument);
    EXPECT_THROW(connectedSets({0.0}, {0.0}, 1.0, {1, 0}, 2.0), std::invalid_argument);
    EXPECT_TRUE(connectedSets({}, {}, 1.0).empty());
}
