// The Slurm job arrays of the workflows (workflows/slurm.mk): `make slurm-validate` writes an
// array script with one task per case and a collect script. Without a cluster, each task is
// run as Slurm would run it (SLURM_ARRAY_TASK_ID, SLURM_CPUS_PER_TASK), then the collect job:
// the report must come out whole. With a live Slurm (scripts/test-slurm.sh starts a one-node
// one on localhost), the same is submitted for real with SUBMIT=1 and waited for; without
// one that test is skipped. Runs are cut at 1 us: this checks the plumbing, not the physics.
#include "RunTool.hpp"
#include "TestPaths.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <thread>

using namespace hvi::test;
namespace fs = std::filesystem;

namespace {

std::string makeSlurmValidate(const fs::path& out, const std::string& extra) {
    return "make -s -C " + sourcePath("workflows").string() +
           " slurm-validate SET=ci RESOLUTION=0.1 END_TIME_US=1 THREADS=1 BIN=" +
           toolPath("hvi-run").parent_path().parent_path().string() + " OUT=" + out.string() +
           " ARCHIVE=" + (out / "kept").string() + " " + extra;
}

int sh(const std::string& command, const fs::path& log) {
    return std::system((command + " >" + log.string() + " 2>&1").c_str());
}

} // namespace

TEST(SlurmWorkflow, ArrayTasksRunAsSlurmWouldAndTheCollectJobWritesTheReport) {
    const fs::path out = tempPath("slurm_local");
    fs::remove_all(out);
    const fs::path log = out.string() + ".log";
    ASSERT_EQ(sh(makeSlurmValidate(out, ""), log), 0) << readFileText(log);
    const fs::path script = out / "slurm" / "validate.sbatch";
    const fs::path collect = out / "slurm" / "validate-collect.sbatch";
    const std::string text = readFileText(script);
    EXPECT_NE(text.find("#SBATCH --array=0-1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("#SBATCH --cpus-per-task=1\n"), std::string::npos) << text;
    EXPECT_NE(readFileText(log).find("submit with SUBMIT=1"), std::string::npos)
        << readFileText(log);
    ASSERT_EQ(sh("bash -n " + script.string() + " && bash -n " + collect.string(), log), 0)
        << readFileText(log);
    for (int task : {1, 0}) { // any order
        ASSERT_EQ(sh("SLURM_ARRAY_TASK_ID=" + std::to_string(task) +
                         " SLURM_CPUS_PER_TASK=1 bash " + script.string(),
                     log),
                  0)
            << readFileText(log);
    }
    for (const char* id : {"A1076", "HITF03147-2"}) {
        EXPECT_TRUE(fs::exists(out / id / "verdict.json")) << id;
    }
    // A task run again finds its target made and runs nothing.
    ASSERT_EQ(sh("SLURM_ARRAY_TASK_ID=0 bash " + script.string(), log), 0) << readFileText(log);
    EXPECT_EQ(readFileText(log).find("run in"), std::string::npos) << readFileText(log);
    ASSERT_EQ(sh("bash " + collect.string(), log), 0) << readFileText(log);
    EXPECT_NE(readFileText(out / "validation.md").find("Not run: 0 of 2"), std::string::npos);
}

TEST(SlurmWorkflow, SubmittedToALiveSlurm) {
    if (std::system("sinfo -h >/dev/null 2>&1") != 0) {
        GTEST_SKIP() << "no live Slurm (scripts/test-slurm.sh starts one on localhost)";
    }
    const fs::path out = tempPath("slurm_live");
    fs::remove_all(out);
    const fs::path log = out.string() + ".log";
    ASSERT_EQ(sh(makeSlurmValidate(out, "SUBMIT=1"), log), 0) << readFileText(log);
    EXPECT_NE(readFileText(log).find("submitted array"), std::string::npos) << readFileText(log);
    // Wait for the collect job's report (the array first, then the collect job).
    const fs::path report = out / "validation.md";
    for (int k = 0; k < 600 && !fs::exists(report); ++k) {
        std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    ASSERT_TRUE(fs::exists(report)) << "no report after 10 min; logs in " << out / "slurm/logs";
    EXPECT_NE(readFileText(report).find("Not run: 0 of 2"), std::string::npos)
        << readFileText(report);
}
