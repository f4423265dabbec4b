// `make -C workflows design` (workflows/design.mk), the README's first command, end to end
// at a coarse spacing and a short end time: every file target of the chain, the verdict set
// beside the default case's test, nothing left to do on a second make, and a bad constraints
// file that stops the chain at its first step with no target behind.
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

std::string makeDesign(const fs::path& out, const std::string& vars,
                       const std::string& target = "design") {
    return "make -s -C " + sourcePath("workflows").string() + " " + target + " RESOLUTION=0.1 " +
           "END_TIME_US=1 THREADS=1 BIN=" +
           toolPath("hvi-run").parent_path().parent_path().string() + " OUT=" + out.string() + " " +
           vars;
}

} // namespace

TEST(DesignWorkflow, DefaultCaseRunsEveryStepAndSaysTheTestsResult) {
    const fs::path out = tempPath("design");
    fs::remove_all(out);
    const fs::path log = out.string() + ".log";
    ASSERT_EQ(std::system((makeDesign(out, "") + " >" + log.string() + " 2>&1").c_str()), 0)
        << readFileText(log);
    const fs::path dir = out / "default";
    for (const char* file : {"sizing.json", "ballistic_limit.svg", "scene.json", "run.h5",
                             "verdict.json", "pictures", "run.xmf", "run.msh"}) {
        EXPECT_TRUE(fs::exists(dir / file)) << file;
    }
    for (const auto& entry : fs::directory_iterator(dir)) {
        EXPECT_EQ(entry.path().filename().string().find(".part."), std::string::npos)
            << "a run's temporary name left behind: " << entry.path();
    }
    EXPECT_EQ(readFileText(dir / "writer"), "foam2layers\n");
    const auto verdict = hvi::io::readJsonFile((dir / "verdict.json").string());
    EXPECT_TRUE(verdict["verdict"].is_string());
    const std::string text = readFileText(log);
    EXPECT_NE(text.find("HITF03147-2"), std::string::npos) << "the test's result: " << text;
    EXPECT_NE(text.find("design: outputs in " + dir.string()), std::string::npos) << text;
    // Nothing left to do (design itself is phony: always out of date to make -q).
    EXPECT_EQ(
        std::system((makeDesign(out, "-q", "-f design.mk " + (dir / "verdict.json").string()) +
                     " >/dev/null 2>&1")
                        .c_str()),
        0);
}

TEST(DesignWorkflow, BadConstraintsStopTheChainWithNoTargetBehind) {
    const fs::path out = tempPath("design_bad");
    fs::remove_all(out);
    const fs::path constraints = tempPath("design_bad_shield.json");
    std::ofstream(constraints) << R"({"threat": {"diameter_mm": -1, "velocity_km_s": 6.5},
                                     "shield": {"type": "single_wall", "thickness_mm": 4}})";
    const fs::path log = out.string() + ".log";
    const int rc = std::system(
        (makeDesign(out, "CONSTRAINTS=" + constraints.string()) + " >" + log.string() + " 2>&1")
            .c_str());
    EXPECT_NE(rc, 0);
    const std::string text = readFileText(log);
    EXPECT_NE(text.find("/threat/diameter_mm"), std::string::npos) << text;
    EXPECT_FALSE(fs::exists(out / "design_bad_shield" / "sizing.json"));
    EXPECT_FALSE(fs::exists(out / "design_bad_shield" / "scene.json"));
}
