// The tools chained as the README runs them: ble-size's sizing.json feeds foam2layers, whose
// scene feeds hvi-run. Each hand-over is where a format mismatch would show.
#include "RunTool.hpp"
#include "io/JsonInput.hpp"
#include "io/RunFileReader.hpp"

#include <filesystem>
#include <gtest/gtest.h>

using namespace hvi::test;

TEST(Pipeline, BleSizeToFoam2LayersToHviRun) {
    const auto constraints = sourcePath("workflows/default/constraints.json");
    const auto sizing = tempPath("pipe.sizing.json");
    const auto scene = tempPath("pipe.scene.json");
    const auto run = tempPath("pipe.h5");
    auto r = runTool("ble-size", constraints.string() + " -q -o " + sizing.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runTool("foam2layers", sizing.string() + " -q --core-discretization sph "
                               "--particle-spacing-mm 0.08 -o " + scene.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << "a clean hand-over: " << r.err;
    const auto doc = hvi::io::readJsonFile(scene.string());
    EXPECT_NO_THROW(hvi::io::validateAgainstSchema(doc, "scene", scene.string()));
    // 2 layers for the 0.5 in, 10 PPI core (thesis notes).
    int layers = 0;
    for (const auto& body : doc["bodies"]) {
        layers += body["role"] == "core_layer" ? 1 : 0;
    }
    EXPECT_EQ(layers, 2);
    r = runTool("hvi-run", scene.string() + " -q --threads 1 --end-time-us 0.2 -o " +
                               run.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    hvi::io::RunFileReader reader(run.string());
    EXPECT_EQ(reader.runFacts()["stop_reason"], "end_time");
}
