// hcomb2rings' input: a honeycomb panel (or a ble-size sizing) made into a ring scene.
#include "FuzzSupport.hpp"
#include "app/Hcomb2RingsTool.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace hvi::fuzz;
    const auto in = writeInput(data, size, "panel.json");
    hvi::app::Hcomb2RingsTool tool;
    runCaptured(tool,
                {"hcomb2rings", in.string(), "-q", "-o", (scratch() / "scene.json").string()});
    return 0;
}
