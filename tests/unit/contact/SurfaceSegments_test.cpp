// The contact's master surface (libcore/contact/KinematicContact): after any pattern of
// erosion, the segments are the edges of exactly one alive element, less those on the axis.
// Checked against an independent count over a map of every element edge, through rounds of
// random erosion of a meshed plate.
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"
#include "contact/KinematicContact.hpp"
#include "fe/FeMesh.hpp"
#include "sph/ParticleSet.hpp"

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

} // namespace

TEST(SurfaceSegments, AreTheEdgesOfExactlyOneAliveElementThroughErosion) {
    json plate = test::plateBody("plate", "bumper", 0.0, 1.0, 2.0);
    plate["discretization"] = "fe";
    const auto scene = test::makeScene({{"geometry", "axisymmetric"},
                                        {"sph", {{"particle_spacing_mm", 0.1}}},
                                        {"bodies", {test::projectileBody(0.5, 1.0), plate}}});
    fe::NodeSet nodes;
    fe::ElementSet elements;
    const auto mesh = fe::meshBody(scene.bodies[1], 1, 2.703, 0.0, true, nodes, elements);
    ASSERT_EQ(mesh.divisionsZ * mesh.divisionsR, elements.size());
    contact::KinematicContact contact({true}, {{false, 0.1}, {true, 0.1}});
    sph::ParticleSet particles;
    std::vector<double> vz, vr, e;
    // The intact plate: its outline less the axis edges, 2 n_z + 2 n_r - n_z.
    contact.vote(particles, {&vz, &vr, &e}, elements, nodes, 1e-3);
    EXPECT_EQ(contact.segmentCount(), mesh.divisionsZ + 2 * mesh.divisionsR);
    EXPECT_EQ(contact.segmentCount(), boundaryEdges(elements, nodes, true));
    std::mt19937 random(5);
    std::uniform_int_distribution<std::size_t> pick(0, elements.size() - 1);
    for (int round = 0; round < 6; ++round) {
        for (int k = 0; k < 25; ++k) {
            elements.alive[pick(random)] = 0;
        }
        contact.vote(particles, {&vz, &vr, &e}, elements, nodes, 1e-3);
        EXPECT_EQ(contact.segmentCount(), boundaryEdges(elements, nodes, true))
            << "after erosion round " << round;
    }
}
