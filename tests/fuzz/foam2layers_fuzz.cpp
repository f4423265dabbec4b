// foam2layers' input: a foam panel (or a ble-size sizing) made into a layered scene.
#include "FuzzSupport.hpp"
#include "app/Foam2LayersTool.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace hvi::fuzz;
    const auto in = writeInput(data, size, "panel.json");
    hvi::app::Foam2LayersTool tool;
    runCaptured(tool,
                {"foam2layers", in.string(), "-q", "-o", (scratch() / "scene.json").string()});
    return 0;
}
