// The tools chained as the README runs them: ble-size's sizing.json feeds foam2layers, whose
// scene feeds hvi-run. Each hand-over is where a format mismatch would show.
#include "RunTool.hpp"
#include "io/JsonInput.hpp"
#include "io/RunFileReader.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace hvi::test;

TEST(Pipeline, BleSizeToFoam2LayersToHviRun) {
    const auto constraints = sourcePath("workflows/default/constraints.json");
    const auto sizing = tempPath("pipe.sizing.json");
    const auto scene = tempPath("pipe.scene.json");
    const auto run = tempPath("pipe.h5");
    auto r = runTool("ble-size", constraints.string() + " -q -o " + sizing.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runTool("foam2layers", sizing.string() +
                                   " -q --core-discretization sph "
                                   "--particle-spacing-mm 0.08 -o " +
                                   scene.string());
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
    r = runTool("hvi-run", scene.string() + " -q --threads 1 --end-time-us 0.2 -o " + run.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    hvi::io::RunFileReader reader(run.string());
    EXPECT_EQ(reader.runFacts()["stop_reason"], "end_time");
}

// A Whipple and a single wall sized by ble-size become scenes without hand-written JSON: the
// sizing's panel block carries the shield's plates, gap and materials to foam2layers.
TEST(Pipeline, BleSizeWhippleAndSingleWallToFoam2Layers) {
    struct Shield {
        std::string tag;
        std::string flags;
        std::vector<std::pair<std::string, double>> plates; ///< role, thickness [mm]
        double wallFrontMm;
    };
    const std::vector<Shield> shields = {
        {"whipple",
         "--type whipple --bumper-mm 0.64 --rear-wall-mm 0.41 --standoff-mm 60 "
         "--rear-wall-material Al2024-T3",
         {{"bumper", 0.64}, {"rear_wall", 0.41}},
         60.64},
        {"single_wall",
         "--type single_wall --thickness-mm 4 --material Al2024-T3",
         {{"rear_wall", 4.0}},
         0.0},
    };
    for (const auto& shield : shields) {
        SCOPED_TRACE(shield.tag);
        const auto sizing = tempPath("pipe_" + shield.tag + ".sizing.json");
        const auto scene = tempPath("pipe_" + shield.tag + ".scene.json");
        auto r = runTool("ble-size", "--diameter-mm 2 --velocity-km-s 6.37 " + shield.flags +
                                         " -q -o " + sizing.string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        r = runTool("foam2layers",
                    sizing.string() + " -q --particle-spacing-mm 0.08 -o " + scene.string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto doc = hvi::io::readJsonFile(scene.string());
        EXPECT_NO_THROW(hvi::io::validateAgainstSchema(doc, "scene", scene.string()));
        EXPECT_EQ(doc["summary"]["shield"], shield.tag);
        std::size_t plates = 0;
        for (const auto& body : doc["bodies"]) {
            for (const auto& [role, thickness] : shield.plates) {
                if (body["role"] == role) {
                    ++plates;
                    EXPECT_NEAR(body["shape"]["thickness_mm"].get<double>(), thickness, 1e-12);
                }
            }
            if (body["role"] == "rear_wall") {
                EXPECT_EQ(body["material"], "Al2024-T3");
                EXPECT_NEAR(body["shape"]["z_front_mm"].get<double>(), shield.wallFrontMm, 1e-12);
            }
        }
        EXPECT_EQ(plates, shield.plates.size());
        EXPECT_EQ(doc["bodies"].size(), shield.plates.size() + 1); // + the projectile
    }
}

// A honeycomb panel sized by ble-size becomes a scene through hcomb2rings: the sizing's panel
// block carries the facesheets, core, cell and foil; without a foil the writer says which key
// of the constraints to add.
TEST(Pipeline, BleSizeHoneycombToHcomb2Rings) {
    const auto constraints = tempPath("pipe_hc.constraints.json");
    const auto sizing = tempPath("pipe_hc.sizing.json");
    const auto scene = tempPath("pipe_hc.scene.json");
    auto writeConstraints = [&](const std::string& foil) {
        std::ofstream(constraints)
            << R"({"threat": {"diameter_mm": 3.6, "velocity_km_s": 6.22, "material": "Al6061-T6"},
                   "shield": {"type": "honeycomb_sandwich", "facesheet_mm": 1.27,
                              "core_thickness_mm": 50.8, "cell_size_mm": 4.7625,
                              "facesheet_material": "Al2024-T3")"
            << foil << "}}";
    };
    writeConstraints(R"(, "foil_thickness_mm": 0.0254, "foil_material": "Al5052-H39")");
    auto r = runTool("ble-size", constraints.string() + " -q -o " + sizing.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto panel = hvi::io::readJsonFile(sizing.string())["panel"];
    EXPECT_EQ(panel["type"], "honeycomb_sandwich");
    EXPECT_DOUBLE_EQ(panel["foil_thickness_mm"].get<double>(), 0.0254);
    r = runTool("hcomb2rings",
                sizing.string() + " -q --particle-spacing-mm 0.08 -o " + scene.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto doc = hvi::io::readJsonFile(scene.string());
    EXPECT_NO_THROW(hvi::io::validateAgainstSchema(doc, "scene", scene.string()));
    int rings = 0;
    for (const auto& body : doc["bodies"]) {
        rings += body["role"] == "core_ring" ? 1 : 0;
        if (body["role"] == "core_ring") {
            EXPECT_EQ(body["material"], "Al5052-H39");
        }
        if (body["role"] == "rear_wall") {
            EXPECT_EQ(body["material"], "Al2024-T3");
            EXPECT_NEAR(body["shape"]["thickness_mm"].get<double>(), 1.27, 1e-12);
        }
    }
    EXPECT_GT(rings, 0);

    // No foil in the constraints: one line naming the missing key, no scene.
    writeConstraints("");
    std::filesystem::remove(scene);
    r = runTool("ble-size", constraints.string() + " -q -o " + sizing.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runTool("hcomb2rings", sizing.string() + " -q -o " + scene.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("foil_thickness_mm"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(scene));
}
