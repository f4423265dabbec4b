// Bumper hole of the source study's particle-size case (thesis_cases.json, calibration
// particle_size_study): a 3.125 mm Al 6061-T6 sphere at 6.847 km/s on a 0.8 mm Al bumper,
// 3 us, SPH only; measured hole 6.7 mm. The study got 6.1 mm (-11 %) at 0.02 mm particles and
// 3 % at 0.015 mm in Autodyn. Run through the whole chain: simulation -> run file ->
// hvi-assess's metric -> --expect comparison.
//
// CI runs the coarse version (0.05 mm, about 30 s on one core; measured 7.02 mm, +4.8 %,
// issue #4 asks for 15 % here). Finer spacings (minutes at 0.03 mm, hours at the calibrated
// 0.015 mm): HVI_UM_SPACING_MM=0.03 build/tests/test_verification_BumperHoleUm3125
#include "SimulationRunFile.hpp"
#include "TestPaths.hpp"
#include "assess/Assessment.hpp"
#include "assess/Expectation.hpp"
#include "io/JsonInput.hpp"

#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

TEST(BumperHoleUm3125, HoleAgainstTheMeasurement) {
    const char* env = std::getenv("HVI_UM_SPACING_MM");
    const double spacing = env ? std::atof(env) : 0.05;
    const double radius = 0.5 * 3.125;
    const json scene = {
        {"id", "UM-3.125"},
        {"sph", {{"particle_spacing_mm", spacing}}},
        {"run",
         {{"end_time_us", 3.0},
          {"stop_debris_speed_km_s", 0.0},
          {"stop_no_new_penetration_us", 0.0}}},
        {"output", {{"snapshot_every_us", 0.5}, {"history_every_steps", 20}}},
        {"domain", {{"radius_mm", 11.0}, {"z_max_mm", 25.0}}},
        {"bodies",
         {{{"name", "projectile"},
           {"role", "projectile"},
           {"material", "Al6061-T6"},
           {"shape",
            {{"type", "sphere"}, {"center_z_mm", -radius - 0.5 * spacing}, {"radius_mm", radius}}},
           {"velocity", {{"z_km_s", 6.847}}}},
          {{"name", "bumper"},
           {"role", "bumper"},
           {"material", "Al6061-T6"},
           {"shape",
            {{"type", "plate"},
             {"z_front_mm", 0.0},
             {"thickness_mm", 0.8},
             {"outer_radius_mm", 10.0}}}}}}};
    const auto path = test::simulateToRunFile(scene, test::tempPath("um3125.h5"));
    const io::RunFileReader reader(path);
    const auto a = assess::assessRun(reader, {});
    ASSERT_TRUE(a.last().hole);
    const json cases = io::readJsonFile(test::sharedPath("validation/thesis_cases.json").string());
    const auto block = assess::selectExpected(cases, "thesis_cases.json", "UM-3.125", "");
    const auto check = assess::compareWithExpected(block, a, {"bumper_hole_diameter_mm"});
    std::printf("spacing %.3f mm: hole %.3f mm (measured 6.7 mm); %s\n", spacing,
                a.last().hole->diameterMm, check.reportLine().c_str());
    for (const auto& m : a.series) {
        std::printf("  t = %.2f us: hole %.3f mm, failed zone %.3f mm\n", m.timeUs,
                    m.hole->diameterMm, m.hole->failedZoneDiameterMm);
    }
    EXPECT_TRUE(check.passed) << check.reportLine();
}
