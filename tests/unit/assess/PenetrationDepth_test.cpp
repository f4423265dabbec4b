// Penetration depth and core damage width (assess/PenetrationDepth.hpp, CoreDamageWidth.hpp)
// on a stack of five 0.2 mm layers (z = 2, 4, ... 10) behind a 0.25 mm bumper, damaged to a
// known depth; and on a honeycomb-like ring wall.
#include "AssessScenes.hpp"
#include "Tolerance.hpp"

#include <gtest/gtest.h>

using namespace hvi;
using test::SyntheticRun;

namespace {

constexpr double kBumperRear = 0.25;

/// Fails the particles of body `name` for which `where(z0, r0)` holds.
template <class Where>
void fail(const SyntheticRun& run, io::ParticleFields& snap, const std::string& name, Where where) {
    run.forBody(snap, name, [&](std::size_t i) {
        if (where(run.initial.z[i], run.initial.r[i])) {
            snap.damage[i] = 1.0;
        }
    });
}

std::vector<std::string> names(const assess::Assessment& a, const std::vector<std::size_t>& b) {
    std::vector<std::string> out;
    for (auto k : b) {
        out.push_back(a.layout.bodies[k].name);
    }
    return out;
}

} // namespace

TEST(PenetrationDepth, UndamagedCoreHasZeroDepth) {
    SyntheticRun run(test::layerScene());
    run.addSnapshot(1.0);
    const auto a = test::assessSynthetic(run, "depth_none");
    ASSERT_TRUE(a.penetrationDepthMm);
    EXPECT_EQ(*a.penetrationDepthMm, 0.0);
    EXPECT_TRUE(a.reachedBodies.empty());
    ASSERT_TRUE(a.coreDamageWidthMm);
    EXPECT_EQ(*a.coreDamageWidthMm, 0.0);
}

TEST(PenetrationDepth, StackDamagedToAKnownDepth) {
    // Layers 1 and 2 failed through their thickness within r < 1 mm, layer 3 only in its
    // front half (rows at z0 = 6.025 and 6.075) within r < 0.5 mm: the deepest failed
    // material reaches z = 6.075 + 0.025 = 6.1, i.e. 5.85 mm behind the bumper's rear face.
    SyntheticRun run(test::layerScene());
    auto& snap = run.addSnapshot(1.0);
    fail(run, snap, "layer1", [](double, double r0) { return r0 < 1.0; });
    fail(run, snap, "layer2", [](double, double r0) { return r0 < 1.0; });
    fail(run, snap, "layer3", [](double z0, double r0) { return r0 < 0.5 && z0 < 6.1; });
    const auto a = test::assessSynthetic(run, "depth_known");
    ASSERT_TRUE(a.penetrationDepthMm);
    EXPECT_TRUE(test::near("depth [mm]", *a.penetrationDepthMm, 6.1 - kBumperRear, 1e-12, 0.0));
    EXPECT_EQ(names(a, a.reachedBodies), (std::vector<std::string>{"layer1", "layer2", "layer3"}));
    EXPECT_EQ(names(a, a.perforatedLayers), (std::vector<std::string>{"layer1", "layer2"}));
    ASSERT_TRUE(a.deepestBody);
    EXPECT_EQ(a.layout.bodies[*a.deepestBody].name, "layer3");
    // Core damage width: failed out to the column centred at 0.975 mm, whose outer side is 1.
    EXPECT_TRUE(test::near("core damage width [mm]", *a.coreDamageWidthMm, 2.0, 1e-12, 0.0));
    EXPECT_FALSE(*a.rearWallPerforated);
}

TEST(PenetrationDepth, ErodedMaterialCountsAsFailed) {
    SyntheticRun run(test::layerScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "layer4", [&](std::size_t i) {
        if (run.initial.r[i] < 0.3) {
            snap.alive[i] = 0;
        }
    });
    const auto a = test::assessSynthetic(run, "depth_eroded");
    EXPECT_TRUE(test::near("depth [mm]", *a.penetrationDepthMm, 8.2 - kBumperRear, 1e-12, 0.0));
}

TEST(PenetrationDepth, ReachingTheRearWallEndsAtItsRearFace) {
    SyntheticRun run(test::layerScene());
    auto& snap = run.addSnapshot(1.0);
    for (const char* layer : {"layer1", "layer2", "layer3", "layer4", "layer5", "rear"}) {
        fail(run, snap, layer, [](double, double r0) { return r0 < 0.2; });
    }
    const auto a = test::assessSynthetic(run, "depth_rear");
    EXPECT_TRUE(test::near("depth [mm]", *a.penetrationDepthMm, 12.5 - kBumperRear, 1e-12, 0.0));
    EXPECT_TRUE(*a.rearWallPerforated);
    EXPECT_EQ(a.perforatedLayers.size(), 5u);
}

TEST(PenetrationDepth, DepthIsTheDeepestOverAllSnapshots) {
    // Damage never heals, but a file could say so; the depth is the worst seen.
    SyntheticRun run(test::layerScene());
    fail(run, run.addSnapshot(1.0), "layer2", [](double, double r0) { return r0 < 0.5; });
    fail(run, run.addSnapshot(2.0), "layer1", [](double, double r0) { return r0 < 0.5; });
    const auto a = test::assessSynthetic(run, "depth_monotone");
    EXPECT_TRUE(test::near("depth [mm]", *a.penetrationDepthMm, 4.2 - kBumperRear, 1e-12, 0.0));
}

TEST(PenetrationDepth, FailedMaterialPushedDeeperKeepsItsInitialDepth) {
    // Layer 1 material failed and pushed 3 mm downstream: the depth is the layer's, the
    // debris depth is where the material went.
    SyntheticRun run(test::layerScene());
    auto& snap = run.addSnapshot(1.0);
    fail(run, snap, "layer1", [](double, double r0) { return r0 < 0.5; });
    run.forBody(snap, "layer1", [&](std::size_t i) {
        if (run.initial.r[i] < 0.5) {
            snap.z[i] += 3.0;
            snap.vz[i] = 1.0;
        }
    });
    const auto a = test::assessSynthetic(run, "depth_pushed");
    EXPECT_TRUE(test::near("depth [mm]", *a.penetrationDepthMm, 2.2 - kBumperRear, 1e-12, 0.0));
    ASSERT_TRUE(a.debrisDepthMm);
    EXPECT_TRUE(test::near("debris depth [mm]", *a.debrisDepthMm, 5.175 - kBumperRear, 1e-12, 0.0));
}

TEST(PenetrationDepth, HoneycombRingIsJudgedAcrossItsWall) {
    // A ring wall 0.1 mm thick (r in [2, 2.1]) spanning the core (z in [1, 11]), failed for
    // z0 < 5 through its thickness: reached to z = 5, and perforated across r.
    nlohmann::json doc = {{"id", "ring-test"},
                          {"sph", {{"particle_spacing_mm", 0.05}}},
                          {"bodies",
                           {test::projectileBody(0.5, 3.0),
                            test::plateBody("bumper", "bumper", 0.0, 0.25, 4.0),
                            {{"name", "ring1"},
                             {"role", "core_ring"},
                             {"material", "Al6061-T6"},
                             {"shape",
                              {{"type", "rectangle"},
                               {"z_min_mm", 1.0},
                               {"z_max_mm", 11.0},
                               {"r_min_mm", 2.0},
                               {"r_max_mm", 2.1}}}},
                            test::plateBody("rear", "rear_wall", 12.0, 0.5, 4.0)}}};
    SyntheticRun run(doc);
    fail(run, run.addSnapshot(1.0), "ring1", [](double z0, double) { return z0 < 5.0; });
    const auto a = test::assessSynthetic(run, "depth_ring");
    EXPECT_TRUE(test::near("depth [mm]", *a.penetrationDepthMm, 5.0 - kBumperRear, 1e-12, 0.0));
    EXPECT_EQ(names(a, a.perforatedLayers), (std::vector<std::string>{"ring1"}));
    EXPECT_TRUE(test::near("core damage width [mm]", *a.coreDamageWidthMm, 4.2, 1e-12, 0.0));
}
