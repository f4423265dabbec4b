// The rear-wall stop waits for hvi-assess's rule (solver/RearWallConfirmation.hpp): the stop
// rule's detector flags an SPH rear wall as soon as one item of another body lies behind its
// rear face, the assessment only with at least Criteria::minCrossingItems (3) items beyond its
// rear surface by more than a spacing and moving outward. One stray particle behind an
// intact wall must not stop the run; five must, with the reason "rear_wall_perforated".
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"

#include <gtest/gtest.h>
#include <string>

using namespace hvi;
using nlohmann::json;

namespace {

/// Moves `count` particles of the slab 0.6 mm behind the wall, flying away at 0.5 km/s, and
/// runs 20 steps; returns the stop reason then ("none" if no rule fires).
std::string stopWithStrays(int count) {
    const json doc = {{"sph", {{"particle_spacing_mm", 0.04}}},
                      {"run",
                       {{"end_time_us", 5.0},
                        {"stop_debris_speed_km_s", 0.0},
                        {"stop_no_new_penetration_us", 0.0}}},
                      {"domain", {{"radius_mm", 1.2}}},
                      {"bodies",
                       {test::plateBody("slab", "projectile", 0.3, 0.12, 0.5),
                        test::plateBody("bumper", "bumper", 0.0, 0.2, 1.0),
                        test::plateBody("wall", "rear_wall", 1.0, 0.2, 1.0)}}};
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    auto& ps = sim.particles();
    int moved = 0;
    for (std::size_t i = 0; i < ps.size() && moved < count; ++i) {
        if (ps.body[i] == 0 && ps.r[i] < 0.5) {
            ps.z[i] = 1.8;
            ps.r[i] = 0.1 + 0.1 * moved;
            ps.vz[i] = 0.5;
            ++moved;
        }
    }
    sim.refreshRates();
    for (int k = 0; k < 20 && !sim.stopReason(); ++k) {
        sim.advance();
    }
    return sim.stopReason().value_or("none");
}

} // namespace

TEST(RearWallConfirmation, OneStrayBehindAnIntactWallDoesNotStopTheRun) {
    EXPECT_EQ(stopWithStrays(1), "none");
}

TEST(RearWallConfirmation, MaterialCrossingTheWallStopsIt) {
    EXPECT_EQ(stopWithStrays(5), "rear_wall_perforated");
}
