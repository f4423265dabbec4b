// hcomb2rings through the built executable: the HITF04150 golden (with the cell size and foil
// assumed in the fixture), the scene conventions, warnings, --mesh and bad input.
#include "SceneWriterCli.hpp"
#include "Tolerance.hpp"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <vector>

using hvi::test::bodiesWithRole;
using hvi::test::dataPath;
using hvi::test::freshOutput;
using hvi::test::mshElementCount;
using hvi::test::near;
using hvi::test::oneErrorLine;
using hvi::test::readJson;
using hvi::test::runTool;
using hvi::test::ToolRun;
using hvi::test::validScene;
using nlohmann::json;

namespace {

const std::string kTool = "hcomb2rings";

// Radii are sums of at most ~10 mm-sized terms: 1e-10 mm absolute is rounding.
constexpr double kRadiusTol = 1e-10;
// Hand values below carry 6 significant digits: half a unit in the last place.
constexpr double kSixDigits = 5e-6;

std::string fixture(const std::string& name) {
    return dataPath("hcomb2rings/" + name).string();
}

json sceneOf(const std::vector<std::string>& args, const std::string& tag,
             ToolRun* runOut = nullptr) {
    const auto out = freshOutput(tag + ".scene.json");
    std::vector<std::string> all = args;
    all.insert(all.end(), {"-o", out.string()});
    const ToolRun run = runTool(kTool, all, tag);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    if (runOut) {
        *runOut = run;
    }
    if (run.exitCode != 0 || !std::filesystem::exists(out)) {
        return json::object();
    }
    return readJson(out);
}

} // namespace

TEST(Hcomb2RingsCli, HelpAndVersionExitZero) {
    const auto help = runTool(kTool, {"--help"}, "hc_help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--cell-size-mm"), std::string::npos);
    EXPECT_NE(help.out.find("all-SPH"), std::string::npos);
    const auto version = runTool(kTool, {"--version"}, "hc_version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_NE(version.out.find("hcomb2rings"), std::string::npos);
}

// HITF04150: 3.6 mm at 6.22 km/s, 1.27 / 50.8 / 1.27 mm; ASSUMED (fixture) 4.7625 mm cells,
// 0.0254 mm Al 6061-T6 foil, ribbon walls double.
// Domain radius: 2 x (1.8 + 52.07 tan 17°) = 2 x 17.7194 = 35.44 -> 36 mm.
// Rings (apothem from the cell centre): D/2 + kD = 2.38125 ... 35.71875 mm (outer radius
// 35.74415 <= 36), 8 rings, all ribbon walls of 2 x 0.0254 = 0.0508 mm, height 50.8 mm, from
// z = 1.27 to 52.07 mm.
// Real core: (8/3)(0.0254/4.7625) = 0.0142222 x 2.70 g/cm3 x 5.08 cm = 0.195072 g/cm2.
// Reduced: 2.70 x 2 Σr w H / R² = 2.70 x 2 x 152.4 x 0.0508 x 50.8 / 1296 / 10
// = 0.163871 g/cm2; ratio 0.840052.
// End time: L = 0.015 + 1.27 + 50.8 + 1.27 = 53.355 mm, 10 L/V + 10 = 95.78 -> 96 us.
TEST(Hcomb2RingsCli, Hitf04150Golden) {
    ToolRun run;
    const json scene = sceneOf({fixture("honeycomb_HITF04150.json")}, "hitf04150", &run);
    ASSERT_FALSE(scene.empty());
    EXPECT_TRUE(validScene(scene));
    EXPECT_EQ(scene["domain"]["radius_mm"].get<double>(), 36.0);
    EXPECT_EQ(scene["run"]["end_time_us"].get<double>(), 96.0);

    const auto rings = bodiesWithRole(scene, "core_ring");
    ASSERT_EQ(rings.size(), 8u);
    for (std::size_t k = 0; k < rings.size(); ++k) {
        const auto& shape = rings[k]["shape"];
        const double mid = 2.38125 + 4.7625 * static_cast<double>(k);
        EXPECT_TRUE(
            near("inner", shape["inner_radius_mm"].get<double>(), mid - 0.0254, kRadiusTol, 0.0));
        EXPECT_TRUE(
            near("outer", shape["outer_radius_mm"].get<double>(), mid + 0.0254, kRadiusTol, 0.0));
        EXPECT_TRUE(near("height", shape["thickness_mm"].get<double>(), 50.8, 1e-12, 0.0));
        EXPECT_TRUE(near("z front", shape["z_front_mm"].get<double>(), 1.27, 1e-12, 0.0));
        EXPECT_EQ(rings[k]["discretization"], "fe");
        EXPECT_EQ(rings[k]["material"], "Al6061-T6");
    }
    const auto& summary = scene["summary"];
    EXPECT_EQ(summary["ring_count"], 8);
    EXPECT_TRUE(near("relative density", summary["relative_density"].get<double>(), 0.0142222, 0.0,
                     kSixDigits));
    EXPECT_TRUE(near("real areal mass", summary["real_core_areal_mass_g_cm2"].get<double>(),
                     0.195072, 0.0, kSixDigits));
    EXPECT_TRUE(near("reduced areal mass", summary["reduced_core_areal_mass_g_cm2"].get<double>(),
                     0.163871, 0.0, kSixDigits));
    EXPECT_TRUE(
        near("ratio", summary["core_areal_mass_ratio"].get<double>(), 0.840052, 0.0, kSixDigits));

    const auto bumper = bodiesWithRole(scene, "bumper");
    const auto rear = bodiesWithRole(scene, "rear_wall");
    ASSERT_EQ(bumper.size(), 1u);
    ASSERT_EQ(rear.size(), 1u);
    EXPECT_EQ(bumper[0]["discretization"], "sph");
    EXPECT_EQ(bumper[0]["shape"]["thickness_mm"].get<double>(), 1.27);
    EXPECT_TRUE(
        near("rear wall z", rear[0]["shape"]["z_front_mm"].get<double>(), 52.07, 1e-12, 0.0));
    EXPECT_EQ(rear[0]["discretization"], "fe");

    // 0.0508 mm rings are above 3 x 0.015 mm: no warning.
    EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("8 rings"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("real 0.195072 g/cm2, reduced 0.163871 g/cm2"), std::string::npos)
        << run.err;
}

// The runnable example of workflows/examples is the fixture of the golden.
TEST(Hcomb2RingsCli, WorkflowExampleRuns) {
    const auto example = hvi::test::sourcePath("workflows/examples/honeycomb_HITF04150.json");
    EXPECT_EQ(hvi::test::readText(example),
              hvi::test::readText(fixture("honeycomb_HITF04150.json")));
    const json scene = sceneOf({example.string()}, "hc_example");
    EXPECT_TRUE(validScene(scene));
    EXPECT_EQ(bodiesWithRole(scene, "core_ring").size(), 8u);
}

// Vertex direction: rings at wall junctions of mean thickness (0.0508 + 0.0254)/2 = 0.0381 mm,
// below 3 x 0.015 mm: the warning asks for a spacing <= 0.0127 mm.
TEST(Hcomb2RingsCli, ThinRingsWarnWithTheSpacingNeeded) {
    ToolRun run;
    const json scene =
        sceneOf({fixture("honeycomb_HITF04150.json"), "--direction", "vertex"}, "vertex", &run);
    ASSERT_FALSE(scene.empty());
    EXPECT_TRUE(validScene(scene));
    EXPECT_NE(run.err.find("hcomb2rings: warning: ring thickness 0.0381 mm is less than 3 "
                           "particle spacings at 0.015 mm; resolving it needs a particle "
                           "spacing <= 0.0127 mm"),
              std::string::npos)
        << run.err;
}

TEST(Hcomb2RingsCli, AllSphScene) {
    const json scene =
        sceneOf({fixture("honeycomb_HITF04150.json"), "--core-discretization", "sph"}, "hc_sph");
    ASSERT_FALSE(scene.empty());
    EXPECT_TRUE(validScene(scene));
    for (const auto& body : scene["bodies"]) {
        EXPECT_EQ(body["discretization"], "sph") << body["name"];
    }
}

// --mesh on a small core: 5 mm high, R = 8 mm, 0.02 mm elements. Rings at 2.38125 and 7.14375
// mm (the next is outside 8 mm), each ceil(0.0508/0.02) = 3 x ceil(5/0.02) = 250 = 750 quads;
// rear wall ceil(1.27/0.02) = 64 x ceil(8/0.02) = 400 = 25600: 27100 in all.
TEST(Hcomb2RingsCli, MeshHasTheStructuredElementCount) {
    const auto out = freshOutput("hcmesh.scene.json");
    const auto msh = freshOutput("hcmesh.scene.msh");
    const auto run = runTool(kTool,
                             {fixture("honeycomb_HITF04150.json"), "--core-thickness-mm", "5",
                              "--domain-radius-mm", "8", "--particle-spacing-mm", "0.02", "--mesh",
                              "-o", out.string()},
                             "hcmesh");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(bodiesWithRole(readJson(out), "core_ring").size(), 2u);
    EXPECT_EQ(mshElementCount(msh), 27100);
}

class Hcomb2RingsBadFile : public ::testing::TestWithParam<std::pair<std::string, std::string>> {};

TEST_P(Hcomb2RingsBadFile, ExitTwoOneLineNoOutput) {
    const auto& [name, pointer] = GetParam();
    const auto out = freshOutput("hcbad_" + name + ".scene.json");
    const auto run = runTool(kTool, {fixture(name), "-o", out.string()}, "hcbad_" + name);
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_TRUE(oneErrorLine(run, kTool, fixture(name), pointer));
    EXPECT_FALSE(std::filesystem::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, Hcomb2RingsBadFile,
    ::testing::Values(
        std::pair{std::string("bad_foil_too_thick.json"), std::string("/panel/foil_thickness_mm")},
        std::pair{std::string("bad_missing_cell_size.json"), std::string("/panel/cell_size_mm")},
        std::pair{std::string("bad_unknown_key.json"), std::string("/panel/cell_shape")},
        std::pair{std::string("bad_impact_site.json"), std::string("/panel/impact_site")},
        std::pair{std::string("bad_core_thinner_than_facesheets.json"),
                  std::string("/panel/core_thickness_mm")},
        std::pair{std::string("bad_unused_angle.json"), std::string("/panel/ring_angle_deg")}),
    [](const auto& param) {
        std::string name = param.param.first.substr(4);
        return name.substr(0, name.size() - 5);
    });

TEST(Hcomb2RingsCli, BadFlagIsLabelledFlags) {
    const auto out = freshOutput("hcbadflag.scene.json");
    const auto run = runTool(
        kTool, {fixture("honeycomb_HITF04150.json"), "--cell-size-mm", "-4", "-o", out.string()},
        "hcbadflag");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(oneErrorLine(run, kTool, "<flags>", "/panel/cell_size_mm"));
    EXPECT_FALSE(std::filesystem::exists(out));
}
