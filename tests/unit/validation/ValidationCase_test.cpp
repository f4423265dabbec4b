// The case selections of hvi-validate (validation/ValidationCase.hpp): the interleaved run
// order keeps every case once and takes the shield types in turn.
#include "validation/ValidationCase.hpp"

#include <gtest/gtest.h>
#include <map>
#include <set>

using namespace hvi;
using validation::Shield;

TEST(ValidationCase, InterleavedOrderTakesTheShieldTypesInTurnAndKeepsEveryCaseOnce) {
    const auto cases = validation::selectCases("development");
    const auto order = validation::interleavedByShield(cases);
    ASSERT_EQ(order.size(), cases.size());
    std::set<std::string> ids;
    for (const auto& c : order) {
        ids.insert(c.id);
    }
    EXPECT_EQ(ids.size(), cases.size()) << "a case is repeated or lost";

    // The first three are one of each type, in the order Whipple, foam, honeycomb.
    ASSERT_GE(order.size(), 3u);
    EXPECT_EQ(order[0].shield, Shield::Whipple);
    EXPECT_EQ(order[1].shield, Shield::Foam);
    EXPECT_EQ(order[2].shield, Shield::Honeycomb);

    // Within a type the file order stands, and every prefix is balanced: no type is more
    // than one case ahead of another while all three still have cases left.
    std::map<Shield, std::vector<std::string>> inFile, inOrder;
    for (const auto& c : cases) {
        inFile[c.shield].push_back(c.id);
    }
    std::map<Shield, std::size_t> seen;
    for (const auto& c : order) {
        inOrder[c.shield].push_back(c.id);
        ++seen[c.shield];
        std::size_t lo = order.size(), hi = 0;
        bool allLeft = true;
        for (const auto& [shield, inType] : inFile) {
            lo = std::min(lo, seen[shield]);
            hi = std::max(hi, seen[shield]);
            allLeft = allLeft && seen[shield] < inType.size();
        }
        if (allLeft) {
            EXPECT_LE(hi - lo, 1u) << "after " << c.id;
        }
    }
    EXPECT_EQ(inOrder, inFile);
}
