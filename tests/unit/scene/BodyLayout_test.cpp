// Overlapping bodies and bodies outside the domain are refused before a scene runs
// (scene/BodyLayout.hpp, issue #25 items 3-4); bodies that touch, as layer stacks do, are not.
#include "AssessScenes.hpp"
#include "SceneRun.hpp"
#include "scene/BodyLayout.hpp"
#include "solver/Simulation.hpp"

#include <gtest/gtest.h>

using namespace hvi;

namespace {

scene::Shape disc(double centerZ, double radius) {
    scene::Shape s;
    s.kind = scene::ShapeKind::Sphere;
    s.centerZ = centerZ;
    s.radius = radius;
    return s;
}

scene::Shape box(double z0, double z1, double r0, double r1) {
    scene::Shape s;
    s.kind = scene::ShapeKind::Rectangle;
    s.zMin = z0;
    s.zMax = z1;
    s.rMin = r0;
    s.rMax = r1;
    return s;
}

nlohmann::json twoBodies(double projectileCentreZ) {
    nlohmann::json ball = test::projectileBody(0.5, 3.0);
    ball["shape"]["center_z_mm"] = projectileCentreZ;
    return {{"id", "layout"},
            {"sph", {{"particle_spacing_mm", 0.1}}},
            {"run", {{"end_time_us", 1.0}}},
            {"domain", {{"radius_mm", 5.0}}},
            {"bodies", {ball, test::plateBody("bumper", "bumper", 0.0, 0.5, 5.0)}}};
}

/// The one issue parseScene raises for `doc`, or "" when it accepts it.
std::string refusal(const nlohmann::json& doc) {
    try {
        test::makeScene(doc);
    } catch (const InputError& e) {
        return e.issues().at(0).pointer + ": " + e.issues().at(0).problem;
    }
    return "";
}

} // namespace

TEST(BodyLayout, OverlapDepthsOfDiscsAndBoxes) {
    // Boxes: the smaller of the shared extents; touching is 0.
    EXPECT_NEAR(scene::overlapDepth(box(0, 1, 0, 5), box(0.8, 2, 0, 5)), 0.2, 1e-12);
    EXPECT_DOUBLE_EQ(scene::overlapDepth(box(0, 1, 0, 5), box(1, 2, 0, 5)), 0.0);
    EXPECT_NEAR(scene::overlapDepth(box(0, 1, 0, 5), box(0.5, 2, 4.9, 6)), 0.1, 1e-12);
    // A disc in front of a plate: radius less the gap to its face.
    EXPECT_NEAR(scene::overlapDepth(disc(-0.6, 0.5), box(0, 1, 0, 5)), -0.1, 1e-12);
    EXPECT_NEAR(scene::overlapDepth(disc(-0.3, 0.5), box(0, 1, 0, 5)), 0.2, 1e-12);
    // Its centre inside the plate: radius plus the centre's depth (nearest face 0.3 away).
    EXPECT_NEAR(scene::overlapDepth(disc(0.3, 0.5), box(0, 1, 0, 5)), 0.8, 1e-12);
    // A disc beside a ring that starts off the axis: the distance is radial.
    EXPECT_NEAR(scene::overlapDepth(disc(0.5, 0.5), box(0, 1, 0.7, 2)), -0.2, 1e-12);
    // Two discs on the axis.
    EXPECT_NEAR(scene::overlapDepth(disc(0, 0.5), disc(0.9, 0.5)), 0.1, 1e-12);
}

TEST(BodyLayout, AProjectileInsideItsBumperIsRefused) {
    EXPECT_EQ(refusal(twoBodies(-0.55)), ""); // 0.05 mm in front: apart
    EXPECT_EQ(refusal(twoBodies(-0.48)), ""); // 0.02 mm into it: within half a spacing
    const std::string inside = refusal(twoBodies(0.25));
    EXPECT_EQ(inside.rfind("/bodies/1/shape: overlaps body 'projectile' (/bodies/0) by ", 0), 0u)
        << inside;
}

TEST(BodyLayout, AThinSphPlateIsRefusedAThinFeLayerIsMeshed) {
    auto thin = twoBodies(-0.55);
    thin["bodies"][1]["shape"]["thickness_mm"] = 0.15; // 1.5 spacings
    EXPECT_EQ(refusal(thin), "/bodies/1/shape: thinner than two particle spacings (0.100000 mm): "
                             "it cannot be resolved");
    // The foam layers of a layer stack at a coarse spacing (0.091 mm at 0.08 mm): two elements.
    thin["bodies"][1]["discretization"] = "fe";
    EXPECT_EQ(refusal(thin), "");
    const auto scene = test::makeScene(thin);
    solver::Simulation sim(scene, scene::sceneLibrary(nlohmann::json::object(), "<test>"));
    ASSERT_NE(sim.finiteElements(), nullptr);
    EXPECT_EQ(sim.finiteElements()->elements().size(), 2u * 50u); // 2 through 0.15 mm, 50 in r
}

TEST(BodyLayout, BodiesOutsideTheDomainAreRefused) {
    auto wide = twoBodies(-0.55);
    wide["bodies"][1]["shape"]["outer_radius_mm"] = 8.0;
    EXPECT_EQ(refusal(wide).rfind("/bodies/1/shape: reaches r = 8 mm, beyond the domain radius "
                                  "5 mm",
                                  0),
              0u)
        << refusal(wide);
    auto upstream = twoBodies(-0.55);
    upstream["domain"]["z_min_mm"] = -0.5;
    EXPECT_EQ(refusal(upstream).rfind("/bodies/0/shape: starts at z = -1.05 mm, upstream", 0), 0u)
        << refusal(upstream);
    auto downstream = twoBodies(-0.55);
    downstream["domain"]["z_max_mm"] = 0.3;
    EXPECT_EQ(refusal(downstream).rfind("/bodies/1/shape: ends at z = 0.5 mm, downstream", 0), 0u)
        << refusal(downstream);
}

TEST(BodyLayout, ALayerStackThatTouchesIsAccepted) {
    // Bumper, two layers and a wall face to face, as foam2layers writes them.
    nlohmann::json doc = twoBodies(-0.55);
    doc["bodies"].push_back(test::plateBody("layer1", "core_layer", 0.5, 0.3, 5.0));
    doc["bodies"].push_back(test::plateBody("layer2", "core_layer", 0.8, 0.3, 5.0));
    doc["bodies"].push_back(test::plateBody("wall", "rear_wall", 1.1, 0.5, 5.0));
    EXPECT_EQ(refusal(doc), "");
    EXPECT_EQ(refusal(test::layerScene()), "");
}

TEST(BodyLayout, AProjectileWithNothingInItsPathIsWarnedOf) {
    // As built: the ball flies into its bumper, no warning.
    EXPECT_TRUE(scene::bodyLayoutWarnings(test::makeScene(twoBodies(-0.6))).empty());
    // Flying away from it (the velocity's sign wrong).
    auto away = twoBodies(-0.6);
    away["bodies"][0]["velocity"]["z_km_s"] = -3.0;
    auto w = scene::bodyLayoutWarnings(test::makeScene(away));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("body 'projectile' moves upstream"), std::string::npos) << w[0];
    // Beside it: a ring plate that starts beyond the ball's radius.
    auto beside = twoBodies(-0.6);
    beside["bodies"][1]["shape"]["inner_radius_mm"] = 1.0;
    w = scene::bodyLayoutWarnings(test::makeScene(beside));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("no body lies in its path"), std::string::npos) << w[0];
    // Nothing moves.
    auto still = twoBodies(-0.6);
    still["bodies"][0].erase("velocity");
    w = scene::bodyLayoutWarnings(test::makeScene(still));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("no body moves"), std::string::npos) << w[0];
}
