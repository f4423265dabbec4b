// hvi-run from the command line: a small scene runs to its stop rule and leaves a run file
// and an XDMF sidecar; bad scenes give exit 2, a pointer and no output; --benchmark prints
// throughput.
#include "RunTool.hpp"
#include "io/AtomicOutput.hpp"
#include "io/Checkpoint.hpp"
#include "io/RunFileReader.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <sys/wait.h>

using namespace hvi::test;

namespace {
const char* kScene = R"({"id": "cli-small", "geometry": "axisymmetric",
  "sph": {"particle_spacing_mm": 0.08},
  "run": {"end_time_us": 0.3, "stop_debris_speed_km_s": 0, "stop_no_new_penetration_us": 0},
  "output": {"snapshot_every_us": 0.1},
  "domain": {"radius_mm": 3.5},
  "bodies": [
    {"name": "ball", "role": "projectile", "material": "Al6061-T6",
     "shape": {"type": "sphere", "center_z_mm": -0.6, "radius_mm": 0.5},
     "velocity": {"z_km_s": 3.0}},
    {"name": "plate", "role": "bumper", "material": "Al6061-T6",
     "shape": {"type": "plate", "z_front_mm": 0.0, "thickness_mm": 0.5, "outer_radius_mm": 3.0}}
  ]})";
/// Wall time between the periodic checkpoints of the interrupted runs below.
constexpr double kCheckpointEverySeconds = 0.1;

/// The kScene run to 40 us with a snapshot every 4 us: over a second of wall time on one
/// thread, ten or more times kCheckpointEverySeconds, so a run is still going when its first
/// checkpoint appears (at 8 us it took 0.4 s, and on a quiet machine ended before the
/// checkpoint of a 0.3 s interval).
std::string longScene() {
    std::string text = kScene;
    auto set = [&text](const std::string& from, const std::string& to) {
        text.replace(text.find(from), from.size(), to);
    };
    set("\"end_time_us\": 0.3", "\"end_time_us\": 40.0");
    set("\"snapshot_every_us\": 0.1", "\"snapshot_every_us\": 4.0");
    return text;
}

/// The run file of the long scene run straight through (made once).
std::filesystem::path uninterruptedRun() {
    static const std::filesystem::path run = [] {
        const auto scene = writeTemp("straight.json", longScene());
        const auto path = tempPath("straight.h5");
        std::filesystem::remove(path);
        const auto r =
            runTool("hvi-run", scene.string() + " -o " + path.string() + " --threads 1 -q");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return path;
    }();
    return run;
}

/// A shell command: hvi-run on `scene` into `run` in the background, checkpointing every
/// kCheckpointEverySeconds; once its first checkpoint exists (at most 60 s, and no longer than
/// the run lasts), `kill -SIGNAL` it and wait.
std::string signalAfterFirstCheckpoint(const std::filesystem::path& scene,
                                       const std::filesystem::path& run,
                                       const std::string& signal) {
    const auto checkpoint = hvi::io::checkpointPathFor(run);
    return toolPath("hvi-run").string() + " " + scene.string() + " -o " + run.string() +
           " --threads 1 -q --checkpoint-every-s " + std::to_string(kCheckpointEverySeconds) +
           " & p=$!; i=0; while [ ! -f " + checkpoint.string() +
           " ] && [ $i -lt 6000 ] && kill -0 $p 2>/dev/null; do sleep 0.01; i=$((i+1)); done; " +
           "kill -" + signal + " $p 2>/dev/null; wait $p";
}

/// h5diff's verdict on the snapshots and the history of two run files ("" when identical;
/// /run's wall time and the resumed flag may differ, the computed results not).
std::string resultsDiffer(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::string said;
    for (const char* group : {"/snapshots", "/history"}) {
        const auto out = tempPath("h5diff.out");
        const std::string cmd = "h5diff -r " + a.string() + " " + b.string() + " " + group + " " +
                                group + " >" + out.string() + " 2>&1";
        if (std::system(cmd.c_str()) != 0) {
            std::ifstream in(out);
            std::stringstream text;
            text << in.rdbuf();
            said += std::string(group) + ": " + text.str().substr(0, 2000) + "\n";
        }
    }
    return said;
}
} // namespace

TEST(HviRunCli, SmallSceneWritesRunFileAndSidecar) {
    const auto scene = writeTemp("small.json", kScene);
    const auto run = tempPath("small.h5");
    std::filesystem::remove(run);
    const auto r = runTool("hvi-run", scene.string() + " -o " + run.string() + " --threads 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("end_time"), std::string::npos) << r.err;
    ASSERT_TRUE(std::filesystem::exists(run));
    EXPECT_TRUE(std::filesystem::exists(tempPath("small.xmf")));
    hvi::io::RunFileReader reader(run.string());
    EXPECT_GE(reader.snapshots().size(), 4u); // t = 0, 0.1, 0.2, 0.3
    EXPECT_EQ(reader.runFacts()["stop_reason"], "end_time");
    EXPECT_EQ(reader.scene()["id"], "cli-small");
    const auto history = reader.readHistory();
    ASSERT_FALSE(history.energyError.empty());
    EXPECT_LT(std::fabs(history.energyError.back()), 0.01);

    // The profile: where the wall time went, printed and kept. Its parts are measured inside
    // the run, so they cannot add up to more than the run's wall time (1 ms of clock reads).
    EXPECT_NE(r.err.find("where the "), std::string::npos) << r.err;
    const auto stored = reader.runFacts()["profile"]; // a JSON text attribute
    ASSERT_TRUE(stored.is_string()) << stored;
    const auto profile = nlohmann::json::parse(stored.get<std::string>());
    ASSERT_TRUE(profile.is_object()) << profile;
    double parts = 0.0;
    for (const auto& package : profile["packages"]) {
        parts += package["total_s"].get<double>();
    }
    for (const auto& loop : profile["loop_s"]) {
        parts += loop.get<double>();
    }
    const double wall = profile["wall_time_s"].get<double>();
    EXPECT_GT(parts, 0.0);
    EXPECT_LE(parts, wall + 1e-3) << profile;
    EXPECT_TRUE(profile["packages"].contains("sph")) << profile;
    EXPECT_GT(profile["packages"]["sph"]["sections_s"]["neighbour search"].get<double>(), 0.0);
    EXPECT_EQ(profile["steps"], reader.runFacts()["steps"]);
    const auto& dt = profile["dt_us"];
    EXPECT_LE(dt["min"].get<double>(), dt["median"].get<double>());
    EXPECT_LE(dt["median"].get<double>(), dt["max"].get<double>());
}

TEST(HviRunCli, BadScenesAreRejectedWithoutOutput) {
    struct Case {
        const char* name;
        std::string text;
        const char* pointer;
    };
    std::string unknownMaterial = kScene;
    unknownMaterial.replace(unknownMaterial.find("\"Al6061-T6\""), 11, "\"Unobtainium\"");
    std::string negative = kScene;
    negative.replace(negative.find("\"radius_mm\": 0.5"), 16, "\"radius_mm\": -0.5");
    std::string unknownKey = kScene;
    unknownKey.replace(unknownKey.find("\"end_time_us\""), 13, "\"end_tme_us\"");
    // A body on the axis cannot move radially in axisymmetry (issue #25, item 9).
    std::string radialOnAxis = kScene;
    radialOnAxis.replace(radialOnAxis.find("\"z_km_s\": 3.0"), 13,
                         "\"z_km_s\": 3.0, \"r_km_s\": 0.5");
    const Case cases[] = {{"unknown-material", unknownMaterial, "/bodies/0/material"},
                          {"negative", negative, "/bodies/0/shape/radius_mm"},
                          {"unknown-key", unknownKey, "/run/end_tme_us"},
                          {"radial-on-axis", radialOnAxis, "/bodies/0/velocity/r_km_s"}};
    for (const auto& c : cases) {
        const auto scene = writeTemp(std::string(c.name) + ".json", c.text);
        const auto run = tempPath(std::string(c.name) + ".h5");
        std::filesystem::remove(run);
        const auto r = runTool("hvi-run", scene.string() + " -o " + run.string());
        EXPECT_EQ(r.exitCode, 2) << c.name << ": " << r.err;
        EXPECT_NE(r.err.find(std::string(": ") + c.pointer + ": "), std::string::npos)
            << c.name << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(run)) << c.name;
    }
}

// --check reads and checks a scene as a run would and runs nothing: the same refusals (the
// overlapping bodies of issue #25, item 3, here), and for a good scene one line on stdout with
// what would run; no run file, mesh, lock or checkpoint is written.
TEST(HviRunCli, CheckReadsTheSceneAndRunsNothing) {
    const auto scene = writeTemp("check.json", kScene);
    const auto run = std::filesystem::path(scene).replace_extension(".h5");
    std::filesystem::remove(run);
    const auto ok = runTool("hvi-run", scene.string() + " --check");
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_NE(ok.out.find("scene 'cli-small' can run: 2 bodies, about "), std::string::npos)
        << ok.out;
    EXPECT_NE(ok.out.find("spacing 0.08 mm, to 0.3 us"), std::string::npos) << ok.out;
    for (const char* ext : {".h5", ".msh", ".lock", ".ckpt.h5", ".xmf"}) {
        EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(scene).replace_extension(ext)))
            << ext;
    }
    std::string overlapping = kScene;
    overlapping.replace(overlapping.find("\"center_z_mm\": -0.6"), 19, "\"center_z_mm\": 0.25");
    const auto bad = writeTemp("check-overlap.json", overlapping);
    const auto refused = runTool("hvi-run", bad.string() + " --check");
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_NE(refused.err.find(": /bodies/"), std::string::npos) << refused.err;
    EXPECT_TRUE(refused.out.empty()) << refused.out;
}

// --resume with nothing to resume from used to start the run afresh without a word (issue #25).
TEST(HviRunCli, ResumeWithoutACheckpointIsRefused) {
    const auto scene = writeTemp("noresume.json", kScene);
    const auto run = tempPath("noresume.h5");
    std::filesystem::remove(run);
    std::filesystem::remove(tempPath("noresume.ckpt.h5"));
    const auto r = runTool("hvi-run", scene.string() + " -o " + run.string() + " --resume");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--resume: no checkpoint"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(run));
}

// A run killed outright (SIGKILL, power loss) leaves its checkpoint and the RUN.tmp.PID it
// was writing, and no RUN. --resume used to drop the snapshots before the checkpoint (and make
// did not resume at all); now it carries them over from that temporary and removes it, and
// refuses to resume without it. A checkpoint of another scene is refused.
TEST(HviRunCli, ARunKilledOutrightResumesWithItsEarlierSnapshots) {
    const std::string text = longScene();
    const auto scene = writeTemp("killed.json", text);
    const auto run = tempPath("killed.h5");
    const auto checkpoint = tempPath("killed.ckpt.h5");
    std::filesystem::remove(run);
    std::filesystem::remove(checkpoint);
    // A failed earlier run of this test may have left its temporaries behind.
    while (const auto stale = hvi::io::orphanedTemporary(run)) {
        std::filesystem::remove(*stale);
    }
    // Start it, wait for its first checkpoint, then kill -9.
    const std::string script = signalAfterFirstCheckpoint(scene, run, "9") + "; exit 0";
    ASSERT_EQ(std::system(script.c_str()), 0);
    if (std::filesystem::exists(run)) {
        GTEST_SKIP() << "the run finished before it could be killed (machine too fast)";
    }
    ASSERT_TRUE(std::filesystem::exists(checkpoint)) << "no checkpoint within 60 s";
    ASSERT_TRUE(hvi::io::orphanedTemporary(run).has_value());

    // A checkpoint of another scene with the same point count (the projectile faster) is
    // refused, and nothing is lost by trying (issue #25, item 7).
    std::string other = text;
    other.replace(other.find("\"z_km_s\": 3.0"), 13, "\"z_km_s\": 3.5");
    const auto otherScene = writeTemp("killed-other.json", other);
    const auto refused =
        runTool("hvi-run", otherScene.string() + " -o " + run.string() + " --threads 1 --resume");
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_NE(refused.err.find("/extra/scene_fingerprint: "), std::string::npos) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(run));
    ASSERT_TRUE(hvi::io::orphanedTemporary(run).has_value());

    // Without that temporary the resumed file would start at the checkpoint and lack the
    // impact's first snapshots and history: refused, and nothing written.
    const auto orphan = *hvi::io::orphanedTemporary(run);
    const auto aside = tempPath("killed-aside.h5");
    std::filesystem::rename(orphan, aside);
    const auto lost =
        runTool("hvi-run", scene.string() + " -o " + run.string() + " --threads 1 --resume");
    EXPECT_EQ(lost.exitCode, 2) << lost.err;
    EXPECT_NE(lost.err.find("are gone"), std::string::npos) << lost.err;
    EXPECT_FALSE(std::filesystem::exists(run));
    EXPECT_FALSE(hvi::io::orphanedTemporary(run).has_value());
    std::filesystem::rename(aside, orphan);

    const auto r =
        runTool("hvi-run", scene.string() + " -o " + run.string() + " --threads 1 --resume");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("killed outright"), std::string::npos) << r.err;
    EXPECT_FALSE(hvi::io::orphanedTemporary(run).has_value());
    hvi::io::RunFileReader reader(run.string());
    ASSERT_EQ(reader.snapshots().size(), 11u); // t = 0, 4, ..., 40: none lost, none twice
    EXPECT_EQ(reader.snapshots().front().timeUs, 0.0);
    const auto history = reader.readHistory();
    ASSERT_FALSE(history.timeUs.empty());
    EXPECT_EQ(history.timeUs.front(), 0.0);
    EXPECT_EQ(resultsDiffer(uninterruptedRun(), run), "");
}

// A run stopped by SIGINT (or SIGHUP: a closed terminal) and resumed used to gain a snapshot
// and a history row at the stop and restart its snapshot schedule from there (issue #25, item
// 12); its snapshots and history are now those of the run made straight through.
TEST(HviRunCli, AStoppedAndResumedRunIsTheUninterruptedOne) {
    const auto scene = writeTemp("stopped.json", longScene());
    for (const char* signal : {"INT", "HUP"}) {
        SCOPED_TRACE(signal);
        const auto run = tempPath("stopped.h5");
        const auto checkpoint = tempPath("stopped.ckpt.h5");
        std::filesystem::remove(run);
        std::filesystem::remove(checkpoint);
        // Stop it once its first periodic checkpoint exists, so the stop falls between
        // scheduled snapshots, after some history.
        const std::string script = signalAfterFirstCheckpoint(scene, run, signal) + "; exit $?";
        const int status = std::system(script.c_str());
        ASSERT_TRUE(WIFEXITED(status));
        if (WEXITSTATUS(status) == 0) {
            GTEST_SKIP() << "the run finished before it could be stopped (machine too fast)";
        }
        ASSERT_EQ(WEXITSTATUS(status), 4) << "interrupted";
        ASSERT_TRUE(std::filesystem::exists(run)) << "the partial run file";
        ASSERT_TRUE(std::filesystem::exists(checkpoint));
        EXPECT_NE(resultsDiffer(uninterruptedRun(), run), "") << "a partial run is partial";

        const auto r =
            runTool("hvi-run", scene.string() + " -o " + run.string() + " --threads 1 --resume");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(resultsDiffer(uninterruptedRun(), run), "");
        EXPECT_FALSE(std::filesystem::exists(checkpoint));
        // Its wall time is the whole run's: the part before the stop (at least the interval
        // to the first checkpoint) and this one; a resumed run used to report its last part only.
        const auto facts = hvi::io::RunFileReader(run.string()).runFacts();
        EXPECT_EQ(facts["resumed"], true);
        ASSERT_TRUE(facts["earlier_wall_time_s"].is_number()) << facts.dump();
        EXPECT_GE(facts["earlier_wall_time_s"].get<double>(), kCheckpointEverySeconds);
        EXPECT_DOUBLE_EQ(facts["wall_time_s"].get<double>(),
                         facts["earlier_wall_time_s"].get<double>() +
                             facts["this_wall_time_s"].get<double>());
        EXPECT_NE(r.err.find(" s with the earlier parts)"), std::string::npos) << r.err;
    }
}

// An FE-only scene's summary said "N particles" (its erosion slots) and "0 particle-steps/s";
// it now counts what the scene holds and gives the element throughput.
TEST(HviRunCli, AnFeOnlySceneIsSummarisedInElements) {
    const auto scene = writeTemp("feonly.json", R"({"id": "fe-only", "geometry": "axisymmetric",
      "fe": {"element_size_mm": 0.1},
      "run": {"end_time_us": 0.05, "stop_debris_speed_km_s": 0, "stop_no_new_penetration_us": 0},
      "domain": {"radius_mm": 3.5},
      "bodies": [
        {"name": "flyer", "role": "projectile", "material": "Al6061-T6", "discretization": "fe",
         "shape": {"type": "rectangle", "z_min_mm": -0.5, "z_max_mm": 0.0, "r_min_mm": 0.0,
                   "r_max_mm": 1.0}, "velocity": {"z_km_s": 1.0}},
        {"name": "plate", "role": "rear_wall", "material": "Al6061-T6", "discretization": "fe",
         "shape": {"type": "plate", "z_front_mm": 0.0, "thickness_mm": 0.5, "outer_radius_mm": 3.0}}
      ]})");
    const auto run = tempPath("feonly.h5");
    std::filesystem::remove(run);
    const auto r = runTool("hvi-run", scene.string() + " -o " + run.string() + " --threads 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find(": 0 SPH particles, 200 FE elements, 2 bodies"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("element-steps/s;"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("particle-steps/s"), std::string::npos) << r.err;
}

// The final history row used to be written twice when the last step fell on the history
// cadence.
TEST(HviRunCli, TheLastHistoryRowIsWrittenOnce) {
    std::string text = kScene;
    const std::string from = "\"snapshot_every_us\": 0.1";
    text.replace(text.find(from), from.size(), from + ", \"history_every_steps\": 1");
    const auto scene = writeTemp("everystep.json", text);
    const auto run = tempPath("everystep.h5");
    std::filesystem::remove(run);
    const auto r = runTool("hvi-run", scene.string() + " -o " + run.string() + " --threads 1 -q");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    hvi::io::RunFileReader reader(run.string());
    const auto h = reader.readHistory();
    ASSERT_GE(h.step.size(), 2u);
    for (std::size_t k = 1; k < h.step.size(); ++k) {
        EXPECT_LT(h.step[k - 1], h.step[k]) << "row " << k;
    }
}

// Two hvi-run on one -o both exited 0 and the last rename won (issue #25, item 13): the second
// is refused while the first runs, and the first's lock goes with it.
TEST(HviRunCli, ASecondRunOnTheSameOutputIsRefused) {
    // The long scene, so the first run still holds the lock when the second starts.
    const auto scene = writeTemp("locked.json", longScene());
    const auto run = tempPath("locked.h5");
    const auto lock = tempPath("locked.lock");
    std::filesystem::remove(run);
    // The first run in the background; the second once the first holds the lock.
    const std::string script =
        toolPath("hvi-run").string() + " " + scene.string() + " -o " + run.string() +
        " --threads 1 -q & p=$!; i=0; while [ ! -f " + lock.string() +
        " ] && [ $i -lt 1200 ]; do sleep 0.02; i=$((i+1)); done; " + toolPath("hvi-run").string() +
        " " + scene.string() + " -o " + run.string() + " --threads 1 -q 2>" +
        tempPath("locked.err").string() +
        "; second=$?; wait $p; first=$?; exit $((first * 16 + second))";
    const int status = std::system(script.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2) << "first run's exit * 16 + second's";
    std::ifstream err(tempPath("locked.err"));
    std::stringstream said;
    said << err.rdbuf();
    EXPECT_NE(said.str().find("--output: another hvi-run is writing"), std::string::npos)
        << said.str();
    EXPECT_TRUE(std::filesystem::exists(run)); // the first one's
    EXPECT_FALSE(std::filesystem::exists(lock));
}

TEST(HviRunCli, BenchmarkPrintsThroughput) {
    const auto r = runTool("hvi-run", "--benchmark --resolution-mm 0.1 --benchmark-steps 5 "
                                      "--threads 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("particle-steps/s"), std::string::npos) << r.out;
    // The pair loop's throughput with the flops a pair it assumes (issue #27's roofline).
    EXPECT_NE(r.out.find("inside the support"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("GFLOP/s at 130 flops a pair"), std::string::npos) << r.out;
    // The FE scene reports its element throughput and what an element-step costs against an
    // active particle-step (issue #5's comparison).
    EXPECT_NE(r.out.find("element-steps/s"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("an element-step costs"), std::string::npos) << r.out;
}

TEST(HviRunCli, HelpVersionSchema) {
    EXPECT_EQ(runTool("hvi-run", "--help").exitCode, 0);
    EXPECT_EQ(runTool("hvi-run", "--version").exitCode, 0);
    const auto schema = runTool("hvi-run", "--print-schema");
    EXPECT_EQ(schema.exitCode, 0);
    EXPECT_NE(schema.out.find("particle_spacing_mm"), std::string::npos);
}

TEST(HviRunCli, ResolutionFlagSetsParticleSpacingAndElementSize) {
    // A scene that fixes its FE element size: --resolution-mm refines both discretizations.
    std::string text = kScene;
    text.replace(text.find("\"shape\": {\"type\": \"plate\""), 7,
                 "\"discretization\": \"fe\", \"shape\"");
    text.replace(text.find("\"run\""), 5, "\"fe\": {\"element_size_mm\": 0.1}, \"run\"");
    const auto scene = writeTemp("resolution.json", text);
    const auto run = tempPath("resolution.h5");
    std::filesystem::remove(run);
    const auto r = runTool("hvi-run", scene.string() + " -o " + run.string() +
                                          " --threads 1 --resolution-mm 0.05 --end-time-us 0.01");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    hvi::io::RunFileReader reader(run.string());
    EXPECT_EQ(reader.scene()["sph"]["particle_spacing_mm"], 0.05);
    EXPECT_EQ(reader.scene()["fe"]["element_size_mm"], 0.05);
    // The 0.5 mm x 3 mm plate at 0.05 mm: 10 x 60 elements.
    EXPECT_EQ(reader.snapshots().front().elementCount, 600u);
}

// The scenes the workflows ship (docs/notebook/fe-erosion.md's tables come from them) load and run:
// each at a coarse 0.2 mm for 0.02 us, a smoke test of the files, not of their physics.
TEST(HviRunCli, ShippedCalibrationScenesRun) {
    const auto folder = sourcePath("workflows/erosion-calibration");
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") {
            continue;
        }
        ++count;
        const auto run = tempPath("shipped-" + entry.path().stem().string() + ".h5");
        std::filesystem::remove(run);
        const auto r = runTool("hvi-run", entry.path().string() + " -o " + run.string() +
                                              " -q --threads 1 --resolution-mm 0.2"
                                              " --end-time-us 0.02");
        ASSERT_EQ(r.exitCode, 0) << entry.path() << ": " << r.err;
        hvi::io::RunFileReader reader(run.string());
        EXPECT_EQ(reader.runFacts()["stop_reason"], "end_time") << entry.path();
        EXPECT_EQ(reader.scene()["id"], entry.path().stem().string()) << entry.path();
        std::filesystem::remove(run);
        std::filesystem::remove(std::filesystem::path(run).replace_extension(".xmf"));
        std::filesystem::remove(std::filesystem::path(run).replace_extension(".msh"));
    }
    EXPECT_GE(count, 5u) << "the A1076/A1077 pair and three 3.125 mm Whipple standoffs";
}
