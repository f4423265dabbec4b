// The solver's stop rules (Simulation::stopReason; source study section 5.4): "no new body
// penetrated for 0.25 us" counts as progress an advance of the moving material's front or
// centre by what the stop speed carries it in that window (or a spacing, if less), so material
// still moving faster than the stop speed is never cut short by it.
//
// Scene: a thin SPH slab already past a bumper (so a body counts as penetrated) drifts at
// 0.13 km/s towards a wall 0.58 mm away: it advances 0.0325 mm per 0.25 us, more than the stop
// speed's 0.025 mm but less than the 0.04 mm spacing. With a spacing as the progress step the
// run stopped at about 0.25 us (no_new_penetration) with the slab still in flight, as
// HITF03147-3 stopped with its debris pushing the rear facesheet at 0.7 km/s.
// And the rule waits while the rear wall still moves, or material in front of it still moves
// toward it, faster than the stop speed (a slab ringing on a thick wall).
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

using namespace hvi;
using nlohmann::json;

namespace {

std::string stopOf(double slabSpeed) {
    json slab = test::plateBody("slab", "projectile", 0.3, 0.12, 0.5);
    slab["velocity"] = {{"z_km_s", slabSpeed}};
    const json doc = {{"sph", {{"particle_spacing_mm", 0.04}}},
                      {"run",
                       {{"end_time_us", 1.0},
                        {"stop_debris_speed_km_s", 0.1},
                        {"stop_no_new_penetration_us", 0.25}}},
                      {"domain", {{"radius_mm", 1.2}}},
                      {"bodies",
                       {slab, test::plateBody("bumper", "bumper", 0.0, 0.2, 1.0),
                        test::plateBody("wall", "rear_wall", 1.0, 0.2, 1.0)}}};
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    test::runUntil(sim, 1.0);
    return sim.stopReason().value_or("none");
}

} // namespace

TEST(StopRules, MaterialFasterThanTheStopSpeedKeepsTheRunGoing) {
    EXPECT_EQ(stopOf(0.13), "end_time");
}

TEST(StopRules, MaterialSlowerThanTheStopSpeedStopsIt) {
    // The same slab at 0.08 km/s: the debris-speed rule ends the run.
    EXPECT_EQ(stopOf(0.08), "debris_stopped");
}

namespace {

struct SlabOnWall {
    std::string reason;
    double fastestAt05 = 0.0; ///< fastest wall |vz| or slab vz at 0.5 us [km/s]
};

/// A slab that has passed a bumper strikes a thick rear wall at 0.3 km/s; the wall and the
/// slab ring on. The front of the moving material stops at the wall and the material behind
/// it slows below the stop speed and speeds up again, so the front falls back and stops
/// advancing: before the rear-wall activity check the no-new-penetration rule ended this run
/// at 0.5 us with the wall still moving at more than the stop speed.
SlabOnWall slabOnWall() {
    json slab = test::plateBody("slab", "projectile", 0.3, 0.4, 0.8);
    slab["velocity"] = {{"z_km_s", 0.3}};
    const json doc = {{"sph", {{"particle_spacing_mm", 0.04}}},
                      {"run",
                       {{"end_time_us", 1.5},
                        {"stop_debris_speed_km_s", 0.1},
                        {"stop_no_new_penetration_us", 0.25}}},
                      {"domain", {{"radius_mm", 1.2}}},
                      {"bodies",
                       {slab, test::plateBody("bumper", "bumper", 0.0, 0.2, 1.0),
                        test::plateBody("wall", "rear_wall", 0.74, 0.8, 1.0)}}};
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    SlabOnWall result;
    bool sampled = false;
    test::runUntil(sim, 1.5, [&](const solver::Simulation& s) {
        if (sampled || s.time() < 0.5) {
            return;
        }
        sampled = true;
        const auto& ps = s.particles();
        for (std::size_t i = 0; i < ps.size(); ++i) {
            const bool wall = ps.body[i] == 2;
            const double v = wall ? std::fabs(ps.vz[i]) : (ps.body[i] == 0 ? ps.vz[i] : 0.0);
            result.fastestAt05 = std::max(result.fastestAt05, v);
        }
    });
    result.reason = sim.stopReason().value_or("none");
    return result;
}

} // namespace

TEST(StopRules, NoNewPenetrationWaitsWhileTheRearWallStillMoves) {
    const SlabOnWall run = slabOnWall();
    EXPECT_GT(run.fastestAt05, 0.1); // the old stop time: the wall was still being struck
    EXPECT_NE(run.reason, "no_new_penetration");
}

TEST(StopRules, NoNewPenetrationStillFiresWhenNothingMovesTowardTheRearWall) {
    // Away from the rear wall (r 1.4-2.0 mm, beyond its 1 mm radius) a slab strikes a thick
    // layer at 0.3 km/s and rings on it (slabOnWall's pair, moved aside), so the moving
    // material stops advancing; in front
    // of the wall nothing moves but wall material thrown back off it at 1 km/s (ejecta,
    // moving away from it for good). Nothing moves toward or in the wall: the rule fires.
    json marker = test::plateBody("marker", "projectile", 0.3, 0.12, 0.5);
    json pusher = test::plateBody("pusher", "projectile", 0.3, 0.4, 2.0, 1.4);
    pusher["velocity"] = {{"z_km_s", 0.3}};
    // Wall material thrown back off its front face: a rear_wall body flying upstream.
    json ejecta = test::plateBody("ejecta", "rear_wall", 1.8, 0.08, 0.5);
    ejecta["velocity"] = {{"z_km_s", -1.0}};
    const json doc = {{"sph", {{"particle_spacing_mm", 0.04}}},
                      {"run",
                       {{"end_time_us", 3.0},
                        {"stop_debris_speed_km_s", 0.1},
                        {"stop_no_new_penetration_us", 0.25},
                        {"stop_on_rear_wall_perforation", false}}}, // the ejecta body is "passed"
                      {"domain", {{"radius_mm", 2.2}}},
                      {"bodies",
                       {marker, pusher, test::plateBody("bumper", "bumper", 0.0, 0.2, 1.0),
                        test::plateBody("layer", "core_layer", 0.74, 0.8, 2.0, 1.4), ejecta,
                        test::plateBody("wall", "rear_wall", 2.0, 0.2, 1.0)}}};
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    test::runUntil(sim, 3.0);
    EXPECT_EQ(sim.stopReason().value_or("none"), "no_new_penetration")
        << "at " << sim.time() << ", last progress " << sim.lastProgressTime();
}
