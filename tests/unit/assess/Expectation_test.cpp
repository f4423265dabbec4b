// --expect (assess/Expectation.hpp): picking the expected block out of the shapes it comes
// in (the thesis validation file included), tolerances, and the one-line report.
#include "AssessScenes.hpp"
#include "assess/Expectation.hpp"
#include "io/JsonInput.hpp"

#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;
using test::SyntheticRun;

namespace {

/// A Whipple run whose bumper has a 3.0 mm hole and whose rear wall is intact (NP).
const assess::Assessment& holeRun() {
    static const assess::Assessment a = [] {
        SyntheticRun run(test::whippleScene());
        auto& snap = run.addSnapshot(1.0);
        run.forBody(snap, "bumper", [&](std::size_t i) {
            if (run.initial.r[i] < 1.5) {
                snap.z[i] += 3.0;
                snap.damage[i] = 1.0;
            }
        });
        return test::assessSynthetic(run, "expect_hole");
    }();
    return a;
}

std::string problem(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Expectation, BareBlockMatches) {
    const auto block = assess::selectExpected(json{{"pnp", "NP"}, {"bumper_hole_diameter_mm", 3.2}},
                                              "e.json", std::nullopt, "x");
    const auto e = assess::compareWithExpected(block, holeRun());
    EXPECT_TRUE(e.passed) << e.reportLine();
    ASSERT_EQ(e.checks.size(), 2u);
    // Default: 10 % of 3.2 mm plus two 0.05 mm sampling intervals = 0.42 mm.
    EXPECT_NEAR(*e.checks[1].allowed, 0.42, 1e-12);
    EXPECT_NEAR(*e.checks[1].difference, -0.2, 1e-9);
    EXPECT_EQ(e.reportLine(),
              "expect e.json: PASS: pnp NP (expected NP) ok; bumper_hole_diameter_mm 3 "
              "(expected 3.2, diff -0.2, allowed 0.42) ok");
}

TEST(Expectation, MismatchesAreListed) {
    const auto block = assess::selectExpected(
        json{{"pnp", "P"},
             {"bumper_hole_diameter_mm", 4.0},
             {"tolerances", {{"bumper_hole_diameter_mm", {{"rtol", 0.0}, {"atol", 0.5}}}}}},
        "e.json", std::nullopt, "x");
    const auto e = assess::compareWithExpected(block, holeRun());
    EXPECT_FALSE(e.passed);
    EXPECT_FALSE(e.checks[0].passed);
    EXPECT_FALSE(e.checks[1].passed);
    EXPECT_EQ(*e.checks[1].allowed, 0.5);
    EXPECT_NE(e.reportLine().find("FAIL: pnp NP (expected P) MISMATCH"), std::string::npos)
        << e.reportLine();
    // --check pnp leaves the hole out.
    const auto onlyHole =
        assess::compareWithExpected(block, holeRun(), {"bumper_hole_diameter_mm"});
    EXPECT_EQ(onlyHole.checks.size(), 1u);
}

TEST(Expectation, MetricTheRunCannotGiveFails) {
    // The scene has no core: a core damage width cannot be assessed.
    const auto block = assess::selectExpected(json{{"pnp", "NP"}, {"core_damage_width_mm", 30.5}},
                                              "e.json", std::nullopt, "x");
    const auto e = assess::compareWithExpected(block, holeRun());
    EXPECT_FALSE(e.passed);
    EXPECT_NE(e.reportLine().find("core_damage_width_mm not assessed"), std::string::npos);
}

TEST(Expectation, CaseFromTheThesisFile) {
    const json cases = io::readJsonFile(test::sharedPath("validation/thesis_cases.json").string());
    const auto block = assess::selectExpected(cases, "thesis_cases.json", "UM-3.125", "x");
    EXPECT_EQ(block.caseId, "UM-3.125");
    EXPECT_EQ(block.pointer, "/whipple/0/expected");
    EXPECT_EQ(block.block["bumper_hole_diameter_mm"], 6.7);
    // Without --case, the run's scene id picks the case.
    const auto byScene =
        assess::selectExpected(cases, "thesis_cases.json", std::nullopt, "HITF04151");
    EXPECT_EQ(byScene.block["penetration_depth_mm"], 41.4);
    // Every expected block of the file is valid.
    for (const char* id :
         {"UM-3.125", "A1076", "A1077", "HITF04150", "HITF04151", "HITF04161", "HITF04152",
          "HITF04163", "HITF03147-2", "HITF03147-3", "HITF05036-2", "HITF05036-3"}) {
        EXPECT_NO_THROW(assess::selectExpected(cases, "thesis_cases.json", std::string(id), "x"))
            << id;
    }
}

TEST(Expectation, SingleCaseEntry) {
    const auto block = assess::selectExpected(
        json{{"id", "mine"}, {"velocity_km_s", 3.0}, {"expected", {{"pnp", "NP"}}}}, "c.json",
        std::nullopt, "x");
    EXPECT_EQ(block.caseId, "mine");
}

TEST(Expectation, ProblemsAreInputErrors) {
    const json cases = io::readJsonFile(test::sharedPath("validation/thesis_cases.json").string());
    const std::string nope = problem([&] { assess::selectExpected(cases, "t.json", "NOPE", "x"); });
    EXPECT_EQ(nope.rfind("t.json: /: no case with id 'NOPE' (one of: ", 0), 0u) << nope;
    EXPECT_NE(nope.find("UM-3.125"), std::string::npos) << nope;
    EXPECT_NE(problem([&] {
                  assess::selectExpected(cases, "t.json", std::nullopt, "x");
              }).find("none has the run's scene id 'x'"),
              std::string::npos);
    EXPECT_NE(problem([&] {
                  assess::selectExpected(json{{"pnp", "maybe"}}, "e.json", std::nullopt, "x");
              }).find("e.json: /pnp"),
              std::string::npos);
    EXPECT_NE(
        problem([&] {
            assess::selectExpected(json{{"pnp", "P"}, {"hole_mm", 3}}, "e.json", std::nullopt, "x");
        }).find("e.json: /hole_mm"),
        std::string::npos);
    EXPECT_NE(problem([&] {
                  assess::selectExpected(json::array(), "e.json", std::nullopt, "x");
              }).find("holds no expected block"),
              std::string::npos);
    // A bad block inside a case file is located in the file.
    json bad = {{"cases", {{{"id", "a"}, {"expected", {{"pnp", 1}}}}}}};
    EXPECT_NE(problem([&] {
                  assess::selectExpected(bad, "b.json", "a", "x");
              }).find("b.json: /cases/0/expected/pnp"),
              std::string::npos);
}
