// Assessing a whole run file (assess/Assessment.hpp, Verdict.hpp): how the run ended, what a
// damaged file is told, and that the verdict document matches its schema.
#include "AssessScenes.hpp"
#include "assess/Verdict.hpp"
#include "io/JsonInput.hpp"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <hdf5.h>

using namespace hvi;
using test::Ending;
using test::SyntheticRun;

namespace {

/// Message of the InputError thrown by assessing `path`, or "" when none is.
std::string assessError(const std::filesystem::path& path) {
    try {
        const io::RunFileReader reader(path);
        assess::assessRun(reader, {});
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void deleteLink(const std::filesystem::path& path, const char* link) {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_GE(H5Ldelete(file, link, H5P_DEFAULT), 0);
    H5Fclose(file);
}

} // namespace

TEST(Assessment, CompleteRunGivesASchemaValidVerdict) {
    SyntheticRun run(test::whippleScene());
    run.addSnapshot(1.0);
    const auto a = test::assessSynthetic(run, "status_complete");
    EXPECT_TRUE(a.complete);
    EXPECT_EQ(a.status, "complete");
    const auto v = assess::verdictJson(a);
    nlohmann::json doc = v;
    doc["provenance"] = {{"tool", "hvi-assess"}, {"version", "test"}};
    EXPECT_NO_THROW(io::validateAgainstSchema(doc, "verdict", "verdict"));
    EXPECT_EQ(v["scene_id"], "whipple-test");
    EXPECT_EQ(v["stop_reason"], "end_time");
    EXPECT_EQ(v["wall_time_s"], 12.5);
    EXPECT_EQ(v["counts"]["particles"], run.initial.z.size());
    EXPECT_EQ(v["resolution"]["bumper_items_across"], 10.0);
    EXPECT_EQ(v["energy_error"], -3.0e-3);
    // The projectile still flies at the wall: the NP is provisional, and that is the only
    // warning.
    ASSERT_EQ(v["warnings"].size(), 1u) << v["warnings"].dump();
    EXPECT_NE(v["warnings"][0].get<std::string>().find("NP is provisional"), std::string::npos);
    EXPECT_EQ(v["verdict_final"], false);
}

TEST(Assessment, InterruptedRunIsPartial) {
    SyntheticRun run(test::whippleScene());
    run.addSnapshot(1.0);
    const auto path =
        run.write(test::tempPath("status_partial.h5"), Ending::Partial, {{"wall_time_s", 3.0}});
    const io::RunFileReader reader(path);
    const auto a = assess::assessRun(reader, {});
    EXPECT_FALSE(a.complete);
    EXPECT_EQ(a.status, "partial");
    const auto v = assess::verdictJson(a);
    EXPECT_EQ(v["complete"], false);
    EXPECT_EQ(v["stop_reason"], "interrupted");
    ASSERT_FALSE(a.warnings.empty());
    EXPECT_NE(a.warnings.front().find("partial"), std::string::npos);
}

TEST(Assessment, KilledRunIsUnfinished) {
    SyntheticRun run(test::whippleScene());
    run.addSnapshot(1.0);
    const auto path = run.write(test::tempPath("status_killed.h5"), Ending::Killed);
    const io::RunFileReader reader(path);
    const auto a = assess::assessRun(reader, {});
    EXPECT_FALSE(a.complete);
    EXPECT_EQ(a.status, "unfinished");
    const auto v = assess::verdictJson(a);
    EXPECT_TRUE(v["stop_reason"].is_null());
    EXPECT_TRUE(v["wall_time_s"].is_null());
    EXPECT_TRUE(v["run"].is_null());
    EXPECT_NE(a.warnings.front().find("no /run group"), std::string::npos);
}

TEST(Assessment, MissingDatasetIsNamed) {
    SyntheticRun run(test::whippleScene());
    run.addSnapshot(1.0);
    const auto path = run.write(test::tempPath("bad_missing.h5"));
    deleteLink(path, "/snapshots/000001/Density");
    const std::string message = assessError(path);
    EXPECT_NE(message.find("/snapshots/000001/Density: missing"), std::string::npos) << message;
}

TEST(Assessment, MissingSceneIsNamed) {
    SyntheticRun run(test::whippleScene());
    const auto path = run.write(test::tempPath("bad_scene.h5"));
    deleteLink(path, "/scene");
    EXPECT_NE(assessError(path).find("/scene"), std::string::npos);
}

TEST(Assessment, BodyIdOutsideTheSceneIsNamed) {
    SyntheticRun run(test::whippleScene());
    run.addSnapshot(1.0).bodyId[7] = 9;
    const auto path = run.write(test::tempPath("bad_body.h5"));
    const std::string message = assessError(path);
    EXPECT_NE(message.find("/snapshots/000001/BodyId: particle 7 has body id 9"), std::string::npos)
        << message;
}

// hvi-run --materials lays a library over the built-in one: the scene names a material it does
// not define, and the run file's /materials holds it.
TEST(Assessment, MaterialOfALibraryGivenToTheRunIsKnown) {
    std::ifstream in(test::dataPath("material/user_library.json"));
    const nlohmann::json library = nlohmann::json::parse(in);
    nlohmann::json doc = test::whippleScene();
    doc["materials"] = library["materials"];
    doc["bodies"][2]["material"] = "MyAl";
    SyntheticRun run(doc);
    run.addSnapshot(1.0);
    run.sceneDoc.erase("materials");
    run.materialsText = library["materials"].dump();
    EXPECT_EQ(assessError(run.write(test::tempPath("run_materials.h5"))), "");
}

TEST(Assessment, RunWithoutSnapshotsIsRejected) {
    SyntheticRun run(test::whippleScene());
    run.snapshots.clear();
    run.feSnapshots.clear();
    run.times.clear();
    const auto path = run.write(test::tempPath("bad_empty.h5"));
    EXPECT_NE(assessError(path).find("/snapshots: holds no snapshot"), std::string::npos);
}

TEST(Assessment, ChangedParticleCountFallsBackToTheSceneGeometry) {
    // A snapshot with one particle fewer: no reference positions; the hole is still found
    // from the scene's geometry.
    SyntheticRun run(test::whippleScene());
    auto& snap = run.addSnapshot(1.0);
    run.forBody(snap, "bumper", [&](std::size_t i) {
        if (run.initial.r[i] < 1.5) {
            snap.z[i] += 3.0;
            snap.damage[i] = 1.0;
        }
    });
    io::forEachField(snap, [](const io::FieldSpec& spec, auto& values) {
        if (!values.empty()) {
            values.resize(values.size() - static_cast<std::size_t>(spec.components));
        }
    });
    const auto a = test::assessSynthetic(run, "fallback");
    EXPECT_FALSE(a.referencePositions);
    ASSERT_TRUE(a.last().hole);
    EXPECT_NEAR(a.last().hole->diameterMm, 3.0, 0.1);
}

TEST(Assessment, NpAtTheEndTimeWithMovingDebrisIsProvisional) {
    // The rear wall is intact at the last snapshot, but the run stopped on its end time with
    // the debris still flying at 2 km/s: the NP is flagged as provisional. With the debris
    // at rest it is not.
    for (const double speed : {2.0, 0.0}) {
        SyntheticRun run(test::whippleScene());
        auto& snap = run.addSnapshot(1.0);
        run.forBody(snap, "projectile", [&](std::size_t i) {
            snap.z[i] = 2.0;
            snap.vz[i] = speed;
        });
        const auto a = test::assessSynthetic(run, "np_end_time");
        ASSERT_TRUE(a.rearWallPerforated.has_value());
        EXPECT_FALSE(*a.rearWallPerforated);
        const bool flagged = std::any_of(a.warnings.begin(), a.warnings.end(), [](const auto& w) {
            return w.find("NP is provisional") != std::string::npos;
        });
        EXPECT_EQ(flagged, speed > 0.1) << "debris at " << speed << " km/s";
    }
}
