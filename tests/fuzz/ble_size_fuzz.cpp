// ble-size's input: a constraints document, sized with the ballistic limit curve.
#include "FuzzSupport.hpp"
#include "app/BleSizeTool.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace hvi::fuzz;
    const auto in = writeInput(data, size, "constraints.json");
    hvi::app::BleSizeTool tool;
    runCaptured(tool, {"ble-size", in.string(), "-q", "-o", (scratch() / "sizing.json").string(),
                       "--curve", (scratch() / "curve.csv").string()});
    return 0;
}
