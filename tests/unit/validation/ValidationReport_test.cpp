// The validation report's counting (validation/ValidationReport.hpp): three cases with hand-
// written verdicts (a right P, a false alarm, a P on the axis band alone) and one not run.
#include "TestPaths.hpp"
#include "validation/ValidationReport.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace hvi;
namespace fs = std::filesystem;

namespace {

void writeCase(const fs::path& dir, const std::string& verdict, bool axisOnly, double bleRatio,
               const std::string& solver = "abc1234",
               const nlohmann::json& rearWall = nlohmann::json::object()) {
    fs::create_directories(dir);
    nlohmann::json v = {{"verdict", verdict},          {"damage_grade", "perforation"},
                        {"verdict_final", true},       {"axis_band_only", axisOnly},
                        {"wall_time_s", 10.0},         {"energy_error", 1e-3},
                        {"solver", {{"git", solver}}}, {"rear_wall", rearWall}};
    std::ofstream(dir / "verdict.json") << v.dump();
    nlohmann::json b = {{"performance",
                         {{"verdict", bleRatio >= 1.0 ? "P" : "NP"},
                          {"critical_over_projectile_diameter", 1.0 / bleRatio}}}};
    std::ofstream(dir / "ble.json") << b.dump();
}

} // namespace

TEST(ValidationReport, CountsAgreementPerShieldAndTheConfusionMatrix) {
    const auto cases = validation::selectCases("quick"); // -2 NP, -3 P, A1076 P, A1077 NP
    const fs::path out = test::tempPath("validation_report");
    fs::remove_all(out);
    writeCase(out / "HITF03147-2", "P", false, 1.2); // false alarm; the BLE too
    // Right, perforated to 0.5 mm with spall from out to 1.25 mm: the outer one is its radius.
    writeCase(out / "HITF03147-3", "P", false, 1.3, "abc1234",
              {{"perforation_radius_mm", 0.5}, {"spall_radius_mm", 1.25}});
    writeCase(out / "A1076", "P", true, 1.8, "0ld5017", // right, on the axis band alone
              {{"perforation_radius_mm", 0.12}, {"spall_radius_mm", nullptr}});
    // A1077 not run: only its ble.json.
    fs::create_directories(out / "A1077");
    std::ofstream(out / "A1077" / "ble.json")
        << R"({"performance": {"verdict": "NP", "critical_over_projectile_diameter": 1.25}})";
    const std::string md = validation::validationReport(cases, out, {"quick", "0.04", {}, {}});
    EXPECT_NE(md.find("| source_study foam | 2 | 1/2 (50 %) | 1/2 (50 %) | 1/2 (50 %) |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| source_study whipple | 2 | 1/1 (100 %) | 1/1 (100 %) | 2/2 (100 %) |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("P/P 2, P/NP (missed) 0, NP/P (false alarm) 1, NP/NP 0"), std::string::npos)
        << md;
    EXPECT_NE(md.find("axis band alone: 1"), std::string::npos) << md;
    EXPECT_NE(md.find("Not run: 1 of 4"), std::string::npos) << md;
    EXPECT_NE(md.find("| A1077 | whipple | 2 | 6.77 | NP | not run |"), std::string::npos) << md;
    EXPECT_NE(md.find("| perforation | yes |  | 1.25 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| perforation | yes | yes | 0.12 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| perforation | yes |  |  |"), std::string::npos) << md; // a P, no radius
    EXPECT_NE(md.find("Wall time of the runs: 30 s"), std::string::npos) << md;
    // Which solver made the verdicts (kept ones may be older than the code).
    EXPECT_NE(md.find("Runs made by hvi-run build `0ld5017` (1), `abc1234` (2)."),
              std::string::npos)
        << md;
}

// A run resumed from the checkpoint of a build that did not record the earlier parts' wall
// time counts only its last part: the report marks that figure, and the set's sum, as a lower
// bound. A resumed run that knows its earlier parts is a whole figure.
TEST(ValidationReport, MarksTheWallTimeOfARunTimedByItsLastPartOnly) {
    const auto cases = validation::selectCases("quick");
    const fs::path out = test::tempPath("validation_report_resumed");
    fs::remove_all(out);
    writeCase(out / "HITF03147-2", "NP", false, 0.8);
    writeCase(out / "HITF03147-3", "P", false, 1.3);
    auto withRun = [&](const char* id, const nlohmann::json& run) {
        nlohmann::json v = nlohmann::json::parse(std::ifstream(out / id / "verdict.json"));
        v["run"] = run;
        std::ofstream(out / id / "verdict.json") << v.dump();
    };
    withRun("HITF03147-2", {{"resumed", true}, {"wall_time_s", 10.0}}); // an older build
    withRun("HITF03147-3",
            {{"resumed", true}, {"earlier_wall_time_s", 6.0}, {"this_wall_time_s", 4.0}});
    const std::string md = validation::validationReport(cases, out, {"quick", "0.04", {}, {}});
    EXPECT_NE(md.find("| HITF03147-2 | foam | 1.1 | 6.69 | NP | NP |"), std::string::npos) << md;
    EXPECT_NE(md.find(" | ≥10 | "), std::string::npos) << md;
    EXPECT_EQ(md.find(" | ≥10 | ", md.find(" | ≥10 | ") + 1), std::string::npos) << md;
    EXPECT_NE(md.find("Wall time of the runs: at least 20 s (1 resumed runs timed by their last "
                      "part only, marked ≥)."),
              std::string::npos)
        << md;
}

// The verdict-stability table: the cases that have a kept verdict at another spacing, side by
// side, and how many keep their verdict; a case with none elsewhere is left out of it.
TEST(ValidationReport, TabulatesTheVerdictsKeptAtOtherSpacings) {
    const auto cases = validation::selectCases("quick");
    const fs::path out = test::tempPath("validation_report_stability");
    fs::remove_all(out);
    writeCase(out / "run" / "HITF03147-2", "P", false, 1.2);
    writeCase(out / "run" / "HITF03147-3", "P", false, 1.3);
    writeCase(out / "run" / "A1076", "P", false, 1.8);
    // Kept verdicts at 0.04 mm: one flips, one stays, A1076 was not run there.
    writeCase(out / "k" / "a", "NP", false, 1.2);
    writeCase(out / "k" / "b", "P", true, 1.3);
    fs::create_directories(out / "0.04");
    fs::rename(out / "k" / "a" / "verdict.json", out / "0.04" / "HITF03147-2.json");
    fs::rename(out / "k" / "b" / "verdict.json", out / "0.04" / "HITF03147-3.json");
    // A1077 only at 0.04 mm: listed, but not counted as kept or changed.
    writeCase(out / "k" / "c", "NP", false, 0.8);
    fs::rename(out / "k" / "c" / "verdict.json", out / "0.04" / "A1077.json");
    validation::ReportOptions options{"quick", "0.08", {}, {}};
    options.otherSpacings = {{"0.04", out / "0.04"}};
    const std::string md = validation::validationReport(cases, out / "run", options);
    EXPECT_NE(md.find("1 of the 2 with verdicts at two spacings or more keep their verdict"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| case | shield | test | 0.08 mm | 0.04 mm |"), std::string::npos) << md;
    EXPECT_NE(md.find("| HITF03147-2 | foam | NP | P, perforation, 10 s | NP, perforation, 10 s |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| HITF03147-3 | foam | P | P, perforation, 10 s | P, perforation, axis, "
                      "10 s |"),
              std::string::npos)
        << md;
    EXPECT_EQ(md.find("| A1076 | whipple | P | P"), std::string::npos) << md;
    EXPECT_NE(md.find("| A1077 | whipple | NP | – | NP, perforation, 10 s |"), std::string::npos)
        << md;
    // Without kept verdicts elsewhere there is no table.
    EXPECT_EQ(validation::validationReport(cases, out / "run", {"quick", "0.08", {}, {}})
                  .find("Verdict stability"),
              std::string::npos);
}

// The sensitivity table: the cases that have a kept verdict with another material library,
// side by side, how many keep their verdict under every variant, and each variant's agreement
// with the tests beside the built-in library's on the cases that variant ran.
TEST(ValidationReport, TabulatesTheVerdictsOfEachMaterialVariant) {
    const auto cases = validation::selectCases("quick"); // -2 NP, -3 P, A1076 P, A1077 NP
    const fs::path out = test::tempPath("validation_report_sensitivity");
    fs::remove_all(out);
    writeCase(out / "run" / "HITF03147-2", "P", false, 1.2); // a false alarm
    writeCase(out / "run" / "HITF03147-3", "P", false, 1.3);
    writeCase(out / "run" / "A1076", "P", false, 1.8); // no variant ran it: left out
    auto keep = [&](const std::string& variant, const std::string& id, const std::string& v) {
        writeCase(out / "k" / variant / id, v, false, 1.0);
        fs::create_directories(out / variant / "0.08");
        fs::rename(out / "k" / variant / id / "verdict.json",
                   out / variant / "0.08" / (id + ".json"));
    };
    keep("spall-2.4", "HITF03147-2", "NP"); // moves, and agrees with the test
    keep("spall-2.4", "HITF03147-3", "P");
    keep("spall-0.8", "HITF03147-2", "P"); // -3 not run with it
    validation::ReportOptions options{"quick", "0.08", {}, {}};
    options.variants = {{"spall-0.8", out / "spall-0.8" / "0.08"},
                        {"spall-2.4", out / "spall-2.4" / "0.08"}};
    const std::string md = validation::validationReport(cases, out / "run", options);
    EXPECT_NE(md.find("## Sensitivity to material constants"), std::string::npos) << md;
    EXPECT_NE(md.find("1 of the 2 run with both keep their verdict under every variant run"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("`spall-0.8` 0/1 (0 %) (built-in 0/1 (0 %)); `spall-2.4` 2/2 (100 %) "
                      "(built-in 1/2 (50 %)). Verdicts that move: HITF03147-2.\n"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| case | shield | test | built-in | spall-0.8 | spall-2.4 |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| HITF03147-2 | foam | NP | P, perforation, 10 s | P, perforation, 10 s "
                      "| NP, perforation, 10 s |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| HITF03147-3 | foam | P | P, perforation, 10 s | – | P, perforation, "
                      "10 s |"),
              std::string::npos)
        << md;
    EXPECT_EQ(md.find("| A1076 | whipple | P | P"), std::string::npos) << md;
    // With spall-0.8 alone nothing moves.
    options.variants.pop_back();
    EXPECT_NE(validation::validationReport(cases, out / "run", options)
                  .find("(built-in 0/1 (0 %)). No verdict moves.\n"),
              std::string::npos);
    // Without kept variants there is no section.
    EXPECT_EQ(validation::validationReport(cases, out / "run", {"quick", "0.08", {}, {}})
                  .find("Sensitivity to material"),
              std::string::npos);
}

// The run-cost table sums the runs' profiles by set and shield: the wall time, the packages'
// shares of it, the loop's own work and the time-bin bound (binned over evaluated point-steps,
// summed before the division); a run without a profile is left out of it.
TEST(ValidationReport, SumsTheRunsProfilesByShield) {
    const auto cases = validation::selectCases("quick");
    const fs::path out = test::tempPath("validation_report_cost");
    fs::remove_all(out);
    writeCase(out / "HITF03147-2", "NP", false, 0.8);
    writeCase(out / "HITF03147-3", "P", false, 1.3);
    writeCase(out / "A1076", "P", false, 1.8); // no profile
    auto withProfile = [&](const char* id, double wall, double sph, double fe, double binned,
                           double evaluated) {
        nlohmann::json v = nlohmann::json::parse(std::ifstream(out / id / "verdict.json"));
        const nlohmann::json profile = {
            {"wall_time_s", wall},
            {"steps", 1000},
            {"packages", {{"sph", {{"total_s", sph}}}, {"fe", {{"total_s", fe}}}}},
            {"loop_s", {{"output", 0.1 * wall}}},
            {"time_bins",
             {{"sph", {{"binned_point_steps", binned}, {"evaluated_point_steps", evaluated}}}}}};
        v["run"] = {{"threads", 1}, {"profile", profile.dump()}};
        std::ofstream(out / id / "verdict.json") << v.dump();
    };
    withProfile("HITF03147-2", 100.0, 60.0, 20.0, 30.0, 100.0);
    withProfile("HITF03147-3", 300.0, 120.0, 120.0, 70.0, 300.0);
    const std::string md = validation::validationReport(cases, out, {"quick", "0.04", {}, {}});
    // 400 s: sph 180 (45 %), fe 140 (35 %), loop 40 (10 %); bins (30 + 70) / (100 + 300), where
    // the mean of the runs' fractions would be 27 %.
    EXPECT_NE(md.find("| source_study foam | 2 | 1 | 0.1 | 200 | 300 | 1000 | 45 % | 35 % | 0 % | "
                      "10 % | 25 % | – |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| all | 2 | 1 |"), std::string::npos) << md;
}
