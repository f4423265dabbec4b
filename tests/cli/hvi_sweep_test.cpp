// hvi-sweep and the sweep workflow. The search's start is checked against ble-size itself (the
// equation's wall for the case's projectile must give that projectile as its critical
// diameter); the Makefile's loop, its result files and its resumption are checked with a
// stand-in solver (hvi-run and hvi-assess replaced by scripts whose verdict flips at a known
// wall thickness), so the test takes seconds; the hydrocode's own sweeps are in the docs.
#include "RunTool.hpp"
#include "TestPaths.hpp"
#include "io/JsonInput.hpp"

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <sys/types.h>
#include <vector>

using namespace hvi::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> lines(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) {
        out.push_back(line);
    }
    return out;
}

int countLines(const fs::path& path) {
    return static_cast<int>(lines(path).size());
}

/// A BIN directory with the real scene writer and hvi-sweep, and a solver whose verdict is P
/// for rear walls thinner than 0.8 mm per km/s of impact speed. Each stand-in run appends a
/// line to runs.log.
fs::path standInBin(const fs::path& dir, double runSeconds = 0.0) {
    fs::remove_all(dir);
    for (const char* tool : {"foam2layers", "hvi-sweep"}) {
        fs::create_directories(dir / tool);
        fs::create_symlink(toolPath(tool), dir / tool / tool);
    }
    fs::create_directories(dir / "hvi-run");
    fs::create_directories(dir / "hvi-assess");
    const fs::path run = dir / "hvi-run" / "hvi-run";
    const fs::path assess = dir / "hvi-assess" / "hvi-assess";
    // hvi-run SCENE -o OUT ...: copies the scene as the "run file".
    std::ofstream(run) << "#!/bin/sh\necho \"$1\" >> " << (dir / "runs.log").string() << "\nsleep "
                       << runSeconds << "\ncp \"$1\" \"$3\"\n";
    // hvi-assess RUN -o OUT: P when t_rear < 0.8 V (both read from the scene).
    std::ofstream(assess)
        << "#!/bin/sh\n"
           "t=$(grep -o '\"thickness_mm\": *[0-9.]*' \"$1\" | tail -1 | sed 's/.*: *//')\n"
           "v=$(grep -o '\"z_km_s\": *[0-9.]*' \"$1\" | head -1 | sed 's/.*: *//')\n"
           "p=$(awk -v t=\"$t\" -v v=\"$v\" 'BEGIN { print (t < 0.8 * v) ? \"P\" : \"NP\" }')\n"
           "printf '{\"verdict\": \"%s\", \"verdict_final\": true}\\n' \"$p\" > \"$3\"\n";
    fs::permissions(run, fs::perms::owner_all, fs::perm_options::add);
    fs::permissions(assess, fs::perms::owner_all, fs::perm_options::add);
    return dir;
}

std::string makeCommand(const fs::path& bin, const fs::path& out, const std::string& speeds,
                        const std::string& goal = "sweep") {
    return "make -s -C " + sourcePath("workflows").string() + " -f sweep.mk " + goal +
           " CASE=WPL-0341 PARAMETER=rear_wall SPEEDS='" + speeds +
           "' TOLERANCE_MM=0.2 RESOLUTION=0.2 BIN=" + bin.string() + " OUT=" + out.string() +
           " KEPT=" + (out.string() + ".kept") + " >>" + out.string() + ".log 2>&1";
}

int runMake(const fs::path& bin, const fs::path& out, const std::string& speeds,
            const std::string& goal = "sweep") {
    return std::system(makeCommand(bin, out, speeds, goal).c_str());
}

} // namespace

TEST(HviSweepCli, StartsAtTheWallTheEquationNeeds) {
    const fs::path dir = tempPath("sweep_init/v6.52");
    fs::remove_all(dir.parent_path());
    const auto r = runTool("hvi-sweep", "init --case WPL-0341 --parameter rear_wall "
                                        "--speed-km-s 6.52 --out-dir " +
                                            dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto spec = hvi::io::readJsonFile((dir / "sweep.json").string());
    const double wall = spec["search"]["guess_mm"];
    EXPECT_EQ(spec["search"]["guess_source"], "ballistic limit equation");
    // ble-size with that wall: the case's 3.18 mm sphere is the critical diameter.
    const auto ble =
        runTool("ble-size", "--type whipple --diameter-mm 3.18 --velocity-km-s "
                            "6.52 --bumper-mm 0.84 --standoff-mm 12.7 "
                            "--rear-wall-mm " +
                                std::to_string(wall) + " --projectile-density-g-cm3 2.8 -o -");
    ASSERT_EQ(ble.exitCode, 0) << ble.err;
    const auto sizing = nlohmann::json::parse(ble.out);
    EXPECT_NEAR(sizing["performance"]["critical_diameter_mm"].get<double>(), 3.18, 2e-3)
        << "wall " << wall;
}

TEST(HviSweepCli, RefusesAMissingShieldAndAnotherSweepInTheSameDirectory) {
    const fs::path dir = tempPath("sweep_refuse/v7");
    fs::remove_all(dir.parent_path());
    const auto none = runTool("hvi-sweep", "init --speed-km-s 7 --out-dir " + dir.string());
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_NE(none.err.find("no shield given"), std::string::npos) << none.err;
    EXPECT_FALSE(fs::exists(dir / "sweep.json"));
    const std::string base = "init --case WPL-0341 --speed-km-s 7 --out-dir " + dir.string();
    ASSERT_EQ(runTool("hvi-sweep", base).exitCode, 0);
    EXPECT_EQ(runTool("hvi-sweep", base).exitCode, 0); // the same sweep again: fine
    const auto other = runTool("hvi-sweep", base + " --tolerance-mm 0.3");
    EXPECT_EQ(other.exitCode, 2);
    EXPECT_NE(other.err.find("holds another sweep"), std::string::npos) << other.err;
    const auto nan = runTool("hvi-sweep", base + " --tolerance-mm nan");
    EXPECT_EQ(nan.exitCode, 2) << nan.err;
    const auto next = runTool("hvi-sweep", "next " + tempPath("sweep_refuse/none").string());
    EXPECT_EQ(next.exitCode, 2) << next.err;
}

TEST(HviSweepWorkflow, BracketsTheStandInLimitAndResumes) {
    const fs::path root = tempPath("sweep_make");
    fs::remove_all(root);
    const fs::path bin = standInBin(root / "bin");
    const fs::path out = root / "out";
    ASSERT_EQ(runMake(bin, out, "6 7"), 0) << readFileText(out.string() + ".log");
    const std::string csv = readFileText(out / "sweep.csv");
    EXPECT_TRUE(fs::exists(out / "sweep.svg"));
    for (const double v : {6.0, 7.0}) {
        const auto c = hvi::io::readJsonFile(
            (out / ("v" + std::to_string(static_cast<int>(v))) / "critical.json").string());
        ASSERT_EQ(c["state"], "converged") << c.dump(1);
        const double limit = 0.8 * v;
        EXPECT_LT(c["fail_side_mm"].get<double>(), limit) << c.dump(1);
        EXPECT_GE(c["hold_side_mm"].get<double>(), limit) << c.dump(1);
        EXPECT_LE(c["hold_side_mm"].get<double>() - c["fail_side_mm"].get<double>(), 0.2);
        EXPECT_NE(csv.find(std::to_string(static_cast<int>(v)) + ",rear_wall,converged,"),
                  std::string::npos)
            << csv;
    }
    // Take back one speed's result and the run at its NP end: the next make runs that one
    // point again, and only that one.
    const int runsBefore = countLines(bin / "runs.log");
    const auto c7 = hvi::io::readJsonFile((out / "v7" / "critical.json").string());
    std::string last;
    for (const auto& run : c7["runs"]) {
        if (run["value_mm"] == c7["hold_side_mm"]) {
            last = run["run"];
        }
    }
    ASSERT_FALSE(last.empty()) << c7.dump(1);
    fs::remove(out / "v7" / "critical.json");
    fs::remove(out / "v7" / "points" / last / "verdict.json");
    fs::remove(out / "v7" / "points" / last / "run.h5");
    ASSERT_EQ(runMake(bin, out, "6 7"), 0) << readFileText(out.string() + ".log");
    EXPECT_EQ(countLines(bin / "runs.log"), runsBefore + 1);
    EXPECT_EQ(hvi::io::readJsonFile((out / "v7" / "critical.json").string()), c7);

    // Kept results stand for their searches: kept, the whole output removed, the next make
    // runs nothing and draws the same CSV.
    fs::remove_all(out.string() + ".kept");
    ASSERT_EQ(runMake(bin, out, "6 7", "sweep-keep"), 0) << readFileText(out.string() + ".log");
    EXPECT_TRUE(fs::exists(out.string() + ".kept/v7/critical.json"));
    fs::remove_all(out);
    const int runsKept = countLines(bin / "runs.log");
    ASSERT_EQ(runMake(bin, out, "6 7"), 0) << readFileText(out.string() + ".log");
    EXPECT_EQ(countLines(bin / "runs.log"), runsKept) << "a kept speed was searched again";
    EXPECT_EQ(readFileText(out / "sweep.csv"), csv);
}

TEST(HviSweepWorkflow, AKilledMakeResumesWithoutRedoingFinishedRuns) {
    // The same sweep twice: once straight through, once killed (the whole make, with its
    // sub-makes and the run in progress, by SIGTERM to its process group) after a few runs and
    // made again. The second ends with the same results and runs no finished point again:
    // only the run the kill cut short may appear twice.
    const fs::path root = tempPath("sweep_make_killed");
    fs::remove_all(root);
    const fs::path whole = root / "whole";
    ASSERT_EQ(runMake(standInBin(root / "bin-whole"), whole, "6 7"), 0)
        << readFileText(whole.string() + ".log");

    const fs::path bin = standInBin(root / "bin", 0.3);
    const fs::path out = root / "out";
    const fs::path pidFile = root / "make.pid";
    const std::string background =
        "setsid sh -c \"" + makeCommand(bin, out, "6 7") + "\" & echo $! >" + pidFile.string();
    ASSERT_EQ(std::system(background.c_str()), 0);
    for (int i = 0; i < 300 && countLines(bin / "runs.log") < 3; ++i) {
        std::system("sleep 0.05");
    }
    const pid_t pid = std::stoi(readFileText(pidFile));
    ASSERT_EQ(::kill(-pid, SIGTERM), 0);
    for (int i = 0; i < 300 && ::kill(-pid, 0) == 0; ++i) {
        std::system("sleep 0.05");
    }
    const std::vector<std::string> before = lines(bin / "runs.log");
    ASSERT_GE(before.size(), 3u);
    EXPECT_FALSE(fs::exists(out / "sweep.csv")) << "the kill came after the sweep had ended";

    ASSERT_EQ(runMake(bin, out, "6 7"), 0) << readFileText(out.string() + ".log");
    EXPECT_EQ(readFileText(out / "sweep.csv"), readFileText(whole / "sweep.csv"));
    const std::vector<std::string> after = lines(bin / "runs.log");
    const std::vector<std::string> straight = lines(root / "bin-whole" / "runs.log");
    EXPECT_LE(after.size(), straight.size() + 1);
    for (std::size_t i = 0; i < after.size(); ++i) {
        for (std::size_t j = i + 1; j < after.size(); ++j) {
            const bool cutShort = i + 1 == before.size() && j == before.size();
            EXPECT_TRUE(after[i] != after[j] || cutShort) << "run again: " << after[i];
        }
    }
}
