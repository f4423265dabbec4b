// The surface of an eroding mesh (libcore/fe/SurfaceTopology), contact's master surface:
// after any pattern of erosion, the segments are the edges of exactly one alive element,
// less those on the axis (checked against an independent count over a map of every element
// edge), the chains link a segment to the one starting where it ends, and each node lists
// its alive elements. Through rounds of random erosion of a meshed plate.
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"
#include "fe/FeMesh.hpp"
#include "fe/SurfaceTopology.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <random>
#include <utility>

using namespace hvi;
using nlohmann::json;

namespace {

std::size_t boundaryEdges(const fe::ElementSet& el, const fe::NodeSet& nd, bool axisymmetric) {
    std::map<std::pair<int32_t, int32_t>, int> uses;
    for (std::size_t i = 0; i < el.size(); ++i) {
        if (!el.alive[i]) {
            continue;
        }
        for (int a = 0; a < 4; ++a) {
            const int32_t p = el.node(i, a), q = el.node(i, (a + 1) % 4);
            ++uses[{std::min(p, q), std::max(p, q)}];
        }
    }
    std::size_t count = 0;
    for (const auto& [edge, n] : uses) {
        const bool onAxis = axisymmetric && nd.onAxis[static_cast<std::size_t>(edge.first)] &&
                            nd.onAxis[static_cast<std::size_t>(edge.second)];
        count += n == 1 && !onAxis ? 1 : 0;
    }
    return count;
}

/// Every chain link joins a segment to one starting at its end node (and back), and each
/// node's element list is its alive elements.
void expectConsistent(const fe::SurfaceTopology& s, const fe::ElementSet& el,
                      const fe::NodeSet& nd) {
    for (std::size_t k = 0; k < s.segmentCount(); ++k) {
        if (s.segNext[k] >= 0) {
            const auto next = static_cast<std::size_t>(s.segNext[k]);
            EXPECT_EQ(s.segA[next], s.segB[k]);
            EXPECT_EQ(s.segPrev[next], static_cast<int32_t>(k));
        }
    }
    std::vector<int32_t> count(nd.size(), 0);
    for (std::size_t i = 0; i < el.size(); ++i) {
        for (int a = 0; a < 4 && el.alive[i]; ++a) {
            ++count[static_cast<std::size_t>(el.node(i, a))];
        }
    }
    const auto& nc = s.nodeCorners;
    for (std::size_t n = 0; n < nd.size(); ++n) {
        ASSERT_EQ(nc.offset[n + 1] - nc.offset[n], count[n]) << "node " << n;
        for (int64_t k = nc.offset[n]; k < nc.offset[n + 1]; ++k) {
            // Each listed corner is an alive element's corner at this node.
            const int32_t corner = nc.corners[static_cast<std::size_t>(k)];
            const std::size_t e = fe::NodeCorners::elementOf(corner);
            EXPECT_TRUE(el.alive[e]) << "node " << n;
            EXPECT_EQ(static_cast<std::size_t>(el.node(e, corner % 4)), n) << "node " << n;
        }
    }
}

} // namespace

TEST(SurfaceTopology, AreTheEdgesOfExactlyOneAliveElementThroughErosion) {
    json plate = test::plateBody("plate", "bumper", 0.0, 1.0, 2.0);
    plate["discretization"] = "fe";
    const auto scene = test::makeScene({{"geometry", "axisymmetric"},
                                        {"sph", {{"particle_spacing_mm", 0.1}}},
                                        {"bodies", {test::projectileBody(0.5, 1.0), plate}}});
    fe::NodeSet nodes;
    fe::ElementSet elements;
    const auto mesh = fe::meshBody(scene.bodies[1], 1, 2.703, 0.0, true, nodes, elements);
    ASSERT_EQ(mesh.divisionsZ * mesh.divisionsR, elements.size());
    fe::SurfaceTopology surface;
    // The intact plate: its outline less the axis edges, 2 n_z + 2 n_r - n_z, in one chain.
    EXPECT_TRUE(surface.update(elements, nodes, true));
    EXPECT_FALSE(surface.update(elements, nodes, true)) << "nothing eroded: no rebuild";
    EXPECT_EQ(surface.segmentCount(), mesh.divisionsZ + 2 * mesh.divisionsR);
    EXPECT_EQ(surface.segmentCount(), boundaryEdges(elements, nodes, true));
    EXPECT_EQ(std::count(surface.segNext.begin(), surface.segNext.end(), -1), 1);
    expectConsistent(surface, elements, nodes);
    std::mt19937 random(5);
    std::uniform_int_distribution<std::size_t> pick(0, elements.size() - 1);
    for (int round = 0; round < 6; ++round) {
        for (int k = 0; k < 25; ++k) {
            elements.alive[pick(random)] = 0;
        }
        surface.update(elements, nodes, true);
        EXPECT_EQ(surface.segmentCount(), boundaryEdges(elements, nodes, true))
            << "after erosion round " << round;
        expectConsistent(surface, elements, nodes);
    }
}
