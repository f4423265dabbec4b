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
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"

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
    solver::Simulation sim(scene, solver::sceneLibrary(json::object(), "<test>"));
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
