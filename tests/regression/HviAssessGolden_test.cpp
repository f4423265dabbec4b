// Golden test of hvi-assess on a short real run: a 1 mm Al sphere at 3 km/s on a 0.4 mm Al
// bumper with a 0.5 mm rear wall 2 mm behind it (hvi_assess_golden/scene.json), run in-process
// with solver::Simulation, written like hvi-run writes, assessed, and compared field by field
// with reference/verdict.json under the tolerances of tolerances.json (each with its reason):
// |a - b| <= atol + rtol * |b|, or exact equality.
//
// To regenerate the reference after a deliberate change of the solver or of a metric:
//   HVI_UPDATE_GOLDEN=1 build/tests/test_regression_HviAssessGolden
// and review the diff of reference/verdict.json.
#include "SimulationRunFile.hpp"
#include "TestPaths.hpp"
#include "Tolerance.hpp"
#include "assess/Assessment.hpp"
#include "assess/Verdict.hpp"
#include "io/AtomicOutput.hpp"
#include "io/JsonInput.hpp"

#include <chrono>
#include <cstdlib>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

TEST(HviAssessGolden, VerdictOfAShortRealRun) {
    const auto dir = test::sourcePath("tests/regression/hvi_assess_golden");
    const json scene = io::readJsonFile((dir / "scene.json").string());
    const auto start = std::chrono::steady_clock::now();
    const auto path = test::simulateToRunFile(scene, test::tempPath("golden.h5"));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("golden run: %.1f s\n", seconds);

    const io::RunFileReader reader(path);
    const auto assessment = assess::assessRun(reader, {});
    json verdict = assess::verdictJson(assessment);
    json document = verdict;
    document["provenance"] = {{"tool", "hvi-assess"}, {"version", "test"}};
    ASSERT_NO_THROW(io::validateAgainstSchema(document, "verdict", "verdict"));
    // Volatile: where the file is and how long it took.
    for (const char* key : {"run_file", "wall_time_s", "run", "solver"}) {
        verdict.erase(key);
    }

    const auto referencePath = dir / "reference" / "verdict.json";
    if (std::getenv("HVI_UPDATE_GOLDEN")) {
        io::writeTextAtomically(referencePath, verdict.dump(2) + "\n");
        GTEST_SKIP() << "reference written to " << referencePath;
    }
    const json reference = io::readJsonFile(referencePath.string());
    const json tolerances = io::readJsonFile((dir / "tolerances.json").string());
    for (const auto& field : tolerances.at("fields")) {
        const json::json_pointer pointer(field.at("pointer").get<std::string>());
        ASSERT_TRUE(reference.contains(pointer)) << pointer;
        ASSERT_TRUE(verdict.contains(pointer)) << pointer;
        const json& want = reference.at(pointer);
        const json& got = verdict.at(pointer);
        if (field.value("exact", false) || !want.is_number()) {
            EXPECT_EQ(got, want) << pointer << " (" << field.value("why", "") << ")";
        } else {
            ASSERT_TRUE(got.is_number()) << pointer << " is " << got.dump();
            EXPECT_TRUE(test::near(pointer.to_string(), got.get<double>(), want.get<double>(),
                                   field.value("atol", 0.0), field.value("rtol", 0.0)))
                << field.value("why", "");
        }
    }
}
