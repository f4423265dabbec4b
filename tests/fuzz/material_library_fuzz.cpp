// hvi-run's --materials file: a material library laid over the built-in one, checked with a
// small scene that uses the built-in aluminium (which the library may redefine), then the
// scene's first steps with it (ScenePrelude.hpp).
#include "FuzzSupport.hpp"
#include "ScenePrelude.hpp"
#include "app/HviRunTool.hpp"

#include <fstream>

namespace {
const char* const kScene = R"({
  "id": "fuzz-materials", "geometry": "axisymmetric",
  "sph": {"particle_spacing_mm": 0.25},
  "run": {"end_time_us": 1.0},
  "domain": {"z_min_mm": -3, "z_max_mm": 3, "radius_mm": 3},
  "bodies": [
    {"name": "projectile", "role": "projectile", "material": "Al6061-T6",
     "shape": {"type": "sphere", "center_z_mm": -1.0, "radius_mm": 0.75},
     "velocity": {"z_km_s": 5.0}},
    {"name": "bumper", "role": "bumper", "material": "Al6061-T6",
     "shape": {"type": "plate", "z_front_mm": 0.0, "thickness_mm": 0.5, "outer_radius_mm": 2.5}}
  ]
})";
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace hvi::fuzz;
    static const auto scene = [] {
        const auto p = scratch() / "materials-scene.json";
        std::ofstream(p) << kScene;
        return p;
    }();
    const auto in = writeInput(data, size, "materials.json");
    hvi::app::HviRunTool tool;
    if (runCaptured(
            tool, {"hvi-run", scene.string(), "--check", "-q", "--materials", in.string()}) == 0) {
        runFirstSteps(scene.string(), {.materialsFile = in.string()});
    }
    return 0;
}
