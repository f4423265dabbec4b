#include "app/BuiltinCases.hpp"

namespace hvi::app {

nlohmann::json bumperCaseScene(double spacing) {
    const double radius = 3.125 / 2.0;
    return {
        {"id", "bumper-3.125mm-6.847km_s"},
        {"description", "Source study bumper case: 3.125 mm Al sphere at 6.847 km/s on a 0.8 mm "
                        "Al 6061-T6 plate (measured hole diameter 6.7 mm)"},
        {"geometry", "axisymmetric"},
        {"domain", {{"radius_mm", 10.5},
                    {"radius_reason", "plate cut at 10 mm, 1.5 times the measured hole"},
                    {"z_max_mm", 20.0}}},
        {"sph", {{"particle_spacing_mm", spacing}}},
        {"run", {{"end_time_us", 3.0}, {"stop_no_new_penetration_us", 0.0},
                 {"stop_debris_speed_km_s", 0.0}}},
        {"output", {{"snapshot_every_us", 0.5}}},
        {"bodies",
         {{{"name", "projectile"}, {"role", "projectile"}, {"material", "Al6061-T6"},
           {"shape", {{"type", "sphere"}, {"center_z_mm", -(radius + spacing)},
                      {"radius_mm", radius}}},
           {"velocity", {{"z_km_s", 6.847}}}},
          {{"name", "bumper"}, {"role", "bumper"}, {"material", "Al6061-T6"},
           {"shape", {{"type", "plate"}, {"z_front_mm", 0.0}, {"thickness_mm", 0.8},
                      {"outer_radius_mm", 10.0}}}}}}};
}

} // namespace hvi::app
