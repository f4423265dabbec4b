// `make -C workflows convergence` (workflows/convergence.mk) end to end on a coarse ladder of
// the source study's bumper case, to 0.5 us (seconds): a run per spacing, the report with
// the source study's own figures, the CSV with one row per spacing, the plot, and nothing
// left to do on a second make.
#include "RunTool.hpp"
#include "TestPaths.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace hvi::test;
namespace fs = std::filesystem;

TEST(ConvergenceWorkflow, CoarseLadderOfTheBumperCase) {
    const fs::path out = tempPath("convergence");
    fs::remove_all(out);
    const std::string make = "make -s -C " + sourcePath("workflows").string() +
                             " SPACINGS='0.2 0.16 0.12' END_TIME_US=0.5 BIN=" +
                             toolPath("hvi-run").parent_path().parent_path().string() +
                             " OUT=" + out.string();
    const fs::path log = out.string() + ".log";
    ASSERT_EQ(std::system((make + " -j2 convergence >" + log.string() + " 2>&1").c_str()), 0)
        << readFileText(log);
    const std::string md = readFileText(out / "convergence.md");
    EXPECT_NE(md.find("Case `UM-3.125`: to 0.5 µs with --domain-radius-mm 10"), std::string::npos)
        << md;
    for (const char* row : {"| 0.2 |", "| 0.16 |", "| 0.12 |"}) {
        EXPECT_NE(md.find(row), std::string::npos) << row << "\n" << md;
    }
    EXPECT_NE(md.find("The source study's particle-size study"), std::string::npos) << md;
    EXPECT_NE(md.find("![Error against wall time, log-log](convergence.png)"), std::string::npos)
        << md;
    EXPECT_TRUE(fs::exists(out / "convergence.png"));
    const std::string csv = readFileText(out / "convergence.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4) << csv;
    EXPECT_EQ(std::system((make + " -q -f convergence.mk " + (out / "convergence.md").string() +
                           " >/dev/null 2>&1")
                              .c_str()),
              0);
}
