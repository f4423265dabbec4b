// Stiff and extreme scenes (issue #4, item 6) run to a sensible stop with finite fields and
// no particle ever at r < 0: a 0.1 mm plate hit at 1, 3, 7 and 15 km/s, a steel sphere on an
// Al plate, and bodies touching the axis.
#include "SceneRun.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

namespace {

json thinPlateScene(double speed, const std::string& projectileMaterial) {
    const double spacing = 0.025; // 4 particles across the 0.1 mm plate
    return {{"geometry", "axisymmetric"},
            {"sph", {{"particle_spacing_mm", spacing}}},
            {"run", {{"end_time_us", 0.4}, {"stop_debris_speed_km_s", 0.0},
                     {"stop_no_new_penetration_us", 0.0}}},
            {"domain", {{"radius_mm", 2.5}, {"z_max_mm", 4.0}}},
            {"bodies",
             {{{"name", "sphere"}, {"role", "projectile"}, {"material", projectileMaterial},
               {"shape", {{"type", "sphere"}, {"center_z_mm", -0.3 - spacing},
                          {"radius_mm", 0.3}}},
               {"velocity", {{"z_km_s", speed}}}},
              {{"name", "plate"}, {"role", "bumper"}, {"material", "Al6061-T6"},
               {"shape", {{"type", "plate"}, {"z_front_mm", 0.0}, {"thickness_mm", 0.1},
                          {"outer_radius_mm", 2.0}}}}}}};
}

/// Runs to the end, checking after every step that the state is finite and r >= 0.
void runAndCheck(const json& doc, const std::string& label) {
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    double minR = 1e300;
    bool finite = true;
    test::runUntil(sim, scene.run.endTime, [&](const solver::Simulation& s) {
        const auto& ps = s.particles();
        for (std::size_t i = 0; i < ps.size(); ++i) {
            if (!ps.alive[i]) {
                continue;
            }
            minR = std::min(minR, ps.r[i]);
            finite = finite && std::isfinite(ps.z[i]) && std::isfinite(ps.r[i]) &&
                     std::isfinite(ps.vz[i]) && std::isfinite(ps.e[i]) &&
                     std::isfinite(ps.rho[i]) && std::isfinite(ps.p[i]);
        }
    });
    const auto reason = sim.stopReason();
    std::printf("%s: stop %s at %.3f us, %ld steps, min r %.2e mm, deleted %zu runaway + %zu "
                "outside, energy error %+.2e\n",
                label.c_str(), reason ? reason->c_str() : "-", sim.time(), sim.step(), minR,
                sim.runawayDeleted(), sim.outOfDomainDeleted(), sim.energyError());
    EXPECT_TRUE(finite) << label;
    EXPECT_GE(minR, 0.0) << label;
    ASSERT_TRUE(reason.has_value()) << label;
    EXPECT_EQ(*reason, "end_time") << label;
    // Energy is accounted for, including what deleted particles carried away.
    EXPECT_LT(std::fabs(sim.energyError()), 0.05) << label;
}

} // namespace

TEST(ExtremeCases, ThinPlateFromOneToFifteenKmPerSecond) {
    for (double v : {1.0, 3.0, 7.0, 15.0}) {
        runAndCheck(thinPlateScene(v, "Al6061-T6"), "0.1 mm plate at " + std::to_string(v));
    }
}

TEST(ExtremeCases, SteelSphereOnAluminium) {
    runAndCheck(thinPlateScene(6.0, "Steel4340"), "steel sphere at 6 km/s");
}

TEST(ExtremeCases, BodiesTouchingTheAxis) {
    // A rod on the axis (first column within one spacing of it) hit end-on by a disc that
    // also starts on the axis: the mirror ghosts and the axis reflection keep r >= 0.
    const double s = 0.02;
    json doc = {{"geometry", "axisymmetric"},
                {"sph", {{"particle_spacing_mm", s}}},
                {"run", {{"end_time_us", 0.3}, {"stop_debris_speed_km_s", 0.0},
                         {"stop_no_new_penetration_us", 0.0}}},
                {"domain", {{"radius_mm", 3.0}}},
                {"bodies",
                 {{{"name", "disc"}, {"role", "projectile"}, {"material", "Al6061-T6"},
                   {"shape", {{"type", "rectangle"}, {"z_min_mm", -0.2 - s}, {"z_max_mm", -s},
                              {"r_min_mm", 0.0}, {"r_max_mm", 0.1}}},
                   {"velocity", {{"z_km_s", 5.0}}}},
                  {{"name", "rod"}, {"role", "bumper"}, {"material", "Al6061-T6"},
                   {"shape", {{"type", "rectangle"}, {"z_min_mm", 0.0}, {"z_max_mm", 1.0},
                              {"r_min_mm", 0.0}, {"r_max_mm", 0.3}}}}}}};
    runAndCheck(doc, "on-axis rod");
}
