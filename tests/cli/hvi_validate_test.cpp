// hvi-validate and the validate workflow through the built executables: the case lists, one
// case's inputs (and that the scene writer and ble-size accept them), bad input, and the
// CI-sized `make -C workflows validate SET=ci` end to end at a coarse spacing (0.1 mm: about
// a minute on two cores).
#include "RunTool.hpp"
#include "TestPaths.hpp"
#include "io/JsonInput.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace hvi::test;
namespace fs = std::filesystem;

namespace {

int lineCount(const std::string& text) {
    int n = 0;
    for (char ch : text) {
        n += ch == '\n' ? 1 : 0;
    }
    return n;
}

} // namespace

TEST(HviValidateCli, ListsEveryCaseOfEachSet) {
    // 12 source-study cases (3 Whipple, 8 foam, 1 honeycomb) and 116 development shots.
    EXPECT_EQ(lineCount(runTool("hvi-validate", "list --set source_study").out), 12);
    EXPECT_EQ(lineCount(runTool("hvi-validate", "list --set development").out), 116);
    EXPECT_EQ(lineCount(runTool("hvi-validate", "list").out), 128);
    EXPECT_EQ(runTool("hvi-validate", "list --set quick").out,
              "HITF03147-2\nHITF03147-3\nA1076\nA1077\n");
}

TEST(HviValidateCli, InputsAreAcceptedByTheTools) {
    for (const std::string id : {"WPL-0463", "foam-9323", "hc-A1"}) {
        const fs::path dir = tempPath("validate_inputs/" + id);
        fs::remove_all(dir);
        const auto r = runTool("hvi-validate", "inputs " + id + " --out-dir " + dir.string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::string writer = readFileText(dir / "writer");
        writer.pop_back();
        const auto scene =
            runTool(writer, (dir / "panel.json").string() + " --particle-spacing-mm 0.05 -o " +
                                (dir / "scene.json").string());
        EXPECT_EQ(scene.exitCode, 0) << id << ": " << scene.err;
        const auto ble = runTool("ble-size", (dir / "constraints.json").string() + " -o " +
                                                 (dir / "ble.json").string());
        EXPECT_EQ(ble.exitCode, 0) << id << ": " << ble.err;
    }
}

TEST(HviValidateCli, AnUnknownCaseIsOneLineAndNoOutput) {
    const fs::path dir = tempPath("validate_inputs/nope");
    fs::remove_all(dir);
    const auto r = runTool("hvi-validate", "inputs NOPE-1 --out-dir " + dir.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("/case: no validation case 'NOPE-1'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "panel.json"));
    const auto set = runTool("hvi-validate", "list --set everything");
    EXPECT_EQ(set.exitCode, 2);
    EXPECT_NE(set.err.find("/set"), std::string::npos) << set.err;
}

TEST(HviValidateCli, AMissingKeptDirectoryIsOneLineAndNoReport) {
    const fs::path dir = tempPath("validate_compare");
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path report = dir / "validation.md";
    const auto r = runTool("hvi-validate", "report --set quick --out-dir " + dir.string() +
                                               " --compare-kept " + (dir / "0.04").string() +
                                               " -o " + report.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("/compare_kept: " + (dir / "0.04").string() + " is no directory"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(report));
    const fs::path variant = dir / "spall-0.8" / "0.08";
    const auto s = runTool("hvi-validate", "report --set quick --out-dir " + dir.string() +
                                               " --sensitivity-kept " + variant.string() + " -o " +
                                               report.string());
    EXPECT_EQ(s.exitCode, 2);
    EXPECT_EQ(lineCount(s.err), 1) << s.err;
    EXPECT_NE(s.err.find("/sensitivity_kept: " + variant.string() + " is no directory"),
              std::string::npos)
        << s.err;
    EXPECT_FALSE(fs::exists(report));
}

TEST(HviValidateWorkflow, CiSetRunsEndToEndThroughTheMakefile) {
    const fs::path out = tempPath("validate_ci");
    fs::remove_all(out);
    const std::string command = "make -s -C " + sourcePath("workflows").string() +
                                " validate SET=ci RESOLUTION=0.1 THREADS=1 BIN=" +
                                toolPath("hvi-run").parent_path().parent_path().string() +
                                " OUT=" + out.string() + " >" + (out.string() + ".log") + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << readFileText(out.string() + ".log");
    const std::string report = readFileText(out / "validation.md");
    for (const char* id : {"| HITF03147-2 | foam |", "| A1076 | whipple |"}) {
        EXPECT_NE(report.find(id), std::string::npos) << report;
    }
    EXPECT_NE(report.find("Not run: 0 of 2"), std::string::npos) << report;
    // A progress line after each case (issue #22, item 5), the last one saying all are done.
    const std::string log = readFileText(out.string() + ".log");
    EXPECT_NE(log.find("validate: 1/2 cases done, 1 left, about "), std::string::npos) << log;
    EXPECT_NE(log.find("validate: all 2 cases done"), std::string::npos) << log;
    for (const char* id : {"HITF03147-2", "A1076"}) {
        const auto v = hvi::io::readJsonFile((out / id / "verdict.json").string());
        EXPECT_TRUE(v["verdict"].is_string()) << id;
        EXPECT_TRUE(fs::exists(out / id / "ble.json")) << id;
    }
    // A second make has nothing left to do: every target is there.
    const std::string again = "make -q -C " + sourcePath("workflows").string() +
                              " validate SET=ci RESOLUTION=0.1 BIN=" +
                              toolPath("hvi-run").parent_path().parent_path().string() +
                              " OUT=" + out.string() + " >/dev/null 2>&1";
    EXPECT_EQ(std::system(again.c_str()), 0);
    // A case whose verdict is missing is made again, though the report is newer than all the
    // inputs (with every target secondary, make took the verdict for an intermediate file and
    // left it unmade).
    const fs::path verdict = out / "A1076" / "verdict.json";
    const fs::path aside = out / "A1076" / "verdict.json.aside";
    fs::rename(verdict, aside);
    EXPECT_NE(std::system(again.c_str()), 0) << "make -q found nothing to do without a verdict";
    fs::rename(aside, verdict);

    // Kept verdicts stand for their runs: copied out, the case directory's run and verdict
    // removed, the next make takes the kept verdict and runs nothing.
    const fs::path archive = tempPath("validate_ci_kept");
    fs::remove_all(archive);
    const std::string make = "make -s -C " + sourcePath("workflows").string() +
                             " SET=ci RESOLUTION=0.1 THREADS=1 BIN=" +
                             toolPath("hvi-run").parent_path().parent_path().string() +
                             " OUT=" + out.string() + " ARCHIVE=" + archive.string();
    ASSERT_EQ(std::system((make + " validate-keep >" + out.string() + ".keep.log 2>&1").c_str()), 0)
        << readFileText(out.string() + ".keep.log");
    EXPECT_NE(readFileText(out.string() + ".keep.log").find("validate-keep: 2 new verdicts"),
              std::string::npos)
        << readFileText(out.string() + ".keep.log");
    const std::string kept = readFileText(archive / "A1076.json");
    // The same verdict, with the repository's own path taken out of the paths it names.
    const std::string root = sourcePath("").string();
    EXPECT_EQ(kept.find(root), std::string::npos) << kept.substr(0, 400);
    std::string made = readFileText(out / "A1076" / "verdict.json");
    for (auto at = made.find(root); at != std::string::npos; at = made.find(root)) {
        made.erase(at, root.size());
    }
    EXPECT_EQ(kept, made);
    fs::remove(out / "A1076" / "run.h5");
    fs::remove(out / "A1076" / "verdict.json");
    fs::remove(out / "validation.md");
    ASSERT_EQ(std::system((make + " validate >" + out.string() + ".again.log 2>&1").c_str()), 0)
        << readFileText(out.string() + ".again.log");
    EXPECT_FALSE(fs::exists(out / "A1076" / "run.h5")) << "the kept verdict was run again";
    EXPECT_EQ(readFileText(out / "A1076" / "verdict.json"), kept);
    EXPECT_NE(readFileText(out / "validation.md").find("Not run: 0 of 2"), std::string::npos);

    // A fresh checkout's report from the kept verdicts alone, with nothing run.
    fs::remove_all(out);
    ASSERT_EQ(std::system((make + " validate-ble >" + out.string() + ".ble.log 2>&1").c_str()), 0)
        << readFileText(out.string() + ".ble.log");
    EXPECT_NE(readFileText(out / "validation.md").find("Not run: 0 of 2"), std::string::npos);
    EXPECT_FALSE(fs::exists(out / "A1076" / "scene.json"));
}

// A sensitivity study's selection: VARIANT names a library of workflows/materials/ (an unknown
// one is one make error naming the directory of the variants), ONLY_CASES the cases of the
// set, and the run goes to the variant's own directory with the library given to hvi-run.
TEST(HviValidateWorkflow, AVariantRunsTheChosenCasesWithItsLibrary) {
    const fs::path out = tempPath("validate_variant");
    fs::remove_all(out);
    const std::string make =
        "make -s -C " + sourcePath("workflows").string() +
        " SET=quick RESOLUTION=0.1 BIN=" + toolPath("hvi-run").parent_path().parent_path().string();
    const std::string log = out.string() + ".log";
    EXPECT_NE(std::system((make + " VARIANT=no-such validate-ble >" + log + " 2>&1").c_str()), 0);
    EXPECT_NE(readFileText(log).find("VARIANT=no-such: "), std::string::npos) << readFileText(log);
    EXPECT_NE(readFileText(log).find("(the variants: workflows/materials/*.json)"),
              std::string::npos)
        << readFileText(log);
    EXPECT_NE(std::system((make + " ONLY_CASES=NOPE validate-ble >" + log + " 2>&1").c_str()), 0);
    EXPECT_NE(readFileText(log).find("none of ONLY_CASES=\"NOPE\" is a case of SET=quick"),
              std::string::npos)
        << readFileText(log);
    // The dry run of the chosen case's run: its own directory, the variant's library.
    const std::string dry = make + " -n VARIANT=spall-0.8 ONLY_CASES=A1076 OUT=" + out.string() +
                            " " + (out / "A1076" / "run.h5").string() + " >" + log + " 2>&1";
    ASSERT_EQ(std::system(dry.c_str()), 0) << readFileText(log);
    EXPECT_NE(readFileText(log).find("--materials " +
                                     sourcePath("workflows/materials/spall-0.8.json").string()),
              std::string::npos)
        << readFileText(log);
    // The report of the variant covers only the chosen case.
    ASSERT_EQ(std::system((make + " VARIANT=spall-0.8 ONLY_CASES=A1076 OUT=" + out.string() +
                           " validate-ble >" + log + " 2>&1")
                              .c_str()),
              0)
        << readFileText(log);
    EXPECT_TRUE(fs::exists(out / "A1076" / "ble.json"));
    EXPECT_FALSE(fs::exists(out / "A1077"));
    EXPECT_NE(readFileText(log).find("validate-ble: 1 cases"), std::string::npos)
        << readFileText(log);
}
