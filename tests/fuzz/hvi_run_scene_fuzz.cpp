// hvi-run's input: a scene, checked as `hvi-run --check` checks it, then its first steps
// (ScenePrelude.hpp).
#include "FuzzSupport.hpp"
#include "ScenePrelude.hpp"
#include "app/HviRunTool.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace hvi::fuzz;
    const auto in = writeInput(data, size, "scene.json");
    hvi::app::HviRunTool tool;
    if (runCaptured(tool, {"hvi-run", in.string(), "--check", "-q"}) == 0) {
        runFirstSteps(in.string(), {});
    }
    return 0;
}
