// ble-size's computation in process: a result the equations cannot represent is a failed
// computation, never a number written as null and judged.
#include "app/BleSizing.hpp"
#include "core/Error.hpp"
#include "io/JsonInput.hpp"

#include <gtest/gtest.h>

using hvi::RuntimeFailure;
using hvi::app::computeSizing;
using nlohmann::json;

namespace {

json resolvedFoam(double coreThicknessMm) {
    const json doc = {{"threat", {{"diameter_mm", 3.6}, {"velocity_km_s", 6.76}}},
                      {"shield",
                       {{"type", "foam_sandwich"},
                        {"facesheet_mm", 0.254},
                        {"core_thickness_mm", coreThicknessMm},
                        {"relative_density_percent", 7},
                        {"ppi", 10}}}};
    return hvi::io::withSchemaDefaults(doc, "constraints");
}

} // namespace

TEST(BleSizing, FiniteResultIsJudged) {
    const auto outcome = computeSizing(resolvedFoam(50.8), "c.json");
    EXPECT_TRUE(outcome.sizing["performance"]["critical_diameter_mm"].is_number());
}

// Issue #25: a 1e308 mm core gave d_c = inf, written as null and called NP.
TEST(BleSizing, InfiniteCriticalDiameterFails) {
    try {
        computeSizing(resolvedFoam(1e308), "c.json");
        FAIL() << "an infinite critical diameter was accepted";
    } catch (const RuntimeFailure& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("/performance/critical_diameter_mm"), std::string::npos) << message;
        EXPECT_NE(message.find("inf"), std::string::npos) << message;
    }
}
