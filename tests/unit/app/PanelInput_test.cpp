// The scene writers in process: reading a panel or a ble-size sizing.json (PanelInput), the
// facesheet rules, error relabelling to "<flags>", and the scenes the two tools build.
#include "TestPaths.hpp"
#include "Tolerance.hpp"
#include "app/FlagOverlay.hpp"
#include "app/Foam2LayersTool.hpp"
#include "app/Hcomb2RingsTool.hpp"
#include "app/PanelInput.hpp"
#include "io/JsonInput.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <set>
#include <string>
#include <vector>

using hvi::InputError;
using hvi::app::buildFoamScene;
using hvi::app::buildHoneycombScene;
using hvi::app::FlagOverlay;
using hvi::app::foamPanelInputKind;
using hvi::app::honeycombPanelInputKind;
using hvi::app::loadPanelInput;
using hvi::test::near;
using nlohmann::json;

namespace {

std::string foamFixture(const std::string& name) {
    return hvi::test::dataPath("foam2layers/" + name).string();
}

std::string honeycombFixture(const std::string& name) {
    return hvi::test::dataPath("hcomb2rings/" + name).string();
}

/// Parses flags into an overlay, as the tool's command line would.
struct Flags {
    CLI::App app;
    FlagOverlay overlay;
    explicit Flags(std::vector<std::string> args) {
        hvi::app::addSharedSceneFlags(app, overlay);
        overlay.addNumber(app, "--ppi", "/panel/ppi", "PPI");
        std::reverse(args.begin(), args.end());
        app.parse(args);
    }
};

std::vector<hvi::InputIssue> issuesOf(const std::string& file, const FlagOverlay& flags = {}) {
    try {
        loadPanelInput(file, foamPanelInputKind(), flags);
    } catch (const InputError& e) {
        return e.issues();
    }
    return {};
}

} // namespace

TEST(PanelInput, FoamSpecResolvesDefaultsAndFacesheets) {
    const auto input =
        loadPanelInput(foamFixture("foam_10ppi_2in.json"), foamPanelInputKind(), FlagOverlay{});
    EXPECT_FALSE(input.fromSizing);
    EXPECT_EQ(input.id(), "HITF04151");
    EXPECT_EQ(input.resolved["panel"]["front_facesheet_mm"].get<double>(), 0.254);
    EXPECT_EQ(input.resolved["panel"]["rear_facesheet_mm"].get<double>(), 0.254);
    EXPECT_FALSE(input.resolved["panel"].contains("facesheet_mm"));
    EXPECT_EQ(input.resolved["reduction"]["layer_rule"], "mass");
    EXPECT_EQ(input.resolved["numerics"]["particle_spacing_mm"].get<double>(), 0.015);
    EXPECT_EQ(input.resolved["numerics"]["rear_wall_discretization"], "fe");
    // The resolved input is itself a valid foam panel document (it reproduces the scene).
    EXPECT_NO_THROW(hvi::io::validateAgainstSchema(input.resolved, "foam_panel", "resolved"));
    EXPECT_EQ(input.frame().coreThicknessMm, 50.8);
    EXPECT_EQ(input.threat().velocityKmS, 6.76);
}

TEST(PanelInput, SizingFileKeepsThreatAndPanel) {
    const auto input =
        loadPanelInput(foamFixture("sizing_HITF04151.json"), foamPanelInputKind(), FlagOverlay{});
    EXPECT_TRUE(input.fromSizing);
    EXPECT_EQ(input.id(), "HITF04151-sized");
    EXPECT_FALSE(input.resolved.contains("ble"));
    EXPECT_FALSE(input.resolved["threat"].contains("angle_deg"));
    EXPECT_FALSE(input.resolved["panel"].contains("core_thickness_source"));
    ASSERT_EQ(input.notes.size(), 1u);
    EXPECT_NE(input.notes[0].find("density_g_cm3"), std::string::npos);
}

TEST(PanelInput, HoneycombSizingNeedsTheCoreGeometry) {
    try {
        loadPanelInput(foamFixture("sizing_honeycomb.json"), honeycombPanelInputKind(),
                       FlagOverlay{});
        FAIL() << "a honeycomb sizing without cell size and foil was accepted";
    } catch (const InputError& e) {
        std::string pointers;
        for (const auto& issue : e.issues()) {
            pointers += issue.pointer + ";";
        }
        EXPECT_EQ(pointers, "/panel/cell_size_mm;/panel/foil_thickness_mm;") << e.what();
    }
    // ... which flags can give.
    CLI::App app;
    FlagOverlay overlay;
    overlay.addNumber(app, "--cell-size-mm", "/panel/cell_size_mm", "D");
    overlay.addNumber(app, "--foil-thickness-mm", "/panel/foil_thickness_mm", "t");
    app.parse(
        std::vector<std::string>{"0.0254", "--foil-thickness-mm", "4.7625", "--cell-size-mm"});
    const auto input =
        loadPanelInput(foamFixture("sizing_honeycomb.json"), honeycombPanelInputKind(), overlay);
    EXPECT_TRUE(input.fromSizing);
    EXPECT_EQ(input.resolved["panel"]["cell_size_mm"].get<double>(), 4.7625);
}

TEST(PanelInput, FlagIssuesAreLabelledFlags) {
    Flags flags({"--ppi", "-1", "--velocity-km-s", "200"});
    const auto issues = issuesOf(foamFixture("foam_10ppi_2in.json"), flags.overlay);
    ASSERT_EQ(issues.size(), 2u);
    for (const auto& issue : issues) {
        EXPECT_EQ(issue.file, "<flags>") << issue.format();
    }
}

TEST(PanelInput, FileAndFlagIssuesAreReportedTogether) {
    Flags flags({"--velocity-km-s", "0"});
    std::set<std::string> located;
    for (const auto& issue : issuesOf(foamFixture("bad_ppi_zero.json"), flags.overlay)) {
        located.insert(issue.file + " " + issue.pointer);
    }
    const std::set<std::string> expected = {foamFixture("bad_ppi_zero.json") + " /panel/ppi",
                                            "<flags> /threat/velocity_km_s"};
    EXPECT_EQ(located, expected);
}

TEST(PanelInput, FacesheetFlagReplacesTheFilesSides) {
    Flags flags({"--facesheet-mm", "1"});
    const auto input = loadPanelInput(foamFixture("bad_facesheet_conflict.json"),
                                      foamPanelInputKind(), flags.overlay);
    EXPECT_EQ(input.frame().frontFacesheetMm, 1.0);
    EXPECT_EQ(input.frame().rearFacesheetMm, 1.0);
}

// The library's keys become the tool's pointers: FoamCoreSpec "standoff_mm" is
// /panel/core_thickness_mm, and the message speaks of core_thickness_mm.
TEST(PanelInput, ReductionErrorsPointIntoTheToolsFile) {
    const auto input =
        loadPanelInput(foamFixture("bad_core_one_pore.json"), foamPanelInputKind(), FlagOverlay{});
    try {
        buildFoamScene(input, json::object());
        FAIL() << "a core of one pore was accepted";
    } catch (const InputError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        const auto& issue = e.issues()[0];
        EXPECT_EQ(issue.pointer, "/panel/core_thickness_mm");
        EXPECT_EQ(issue.file, foamFixture("bad_core_one_pore.json"));
        EXPECT_EQ(issue.expected.find("standoff_mm"), std::string::npos) << issue.format();
        EXPECT_NE(issue.expected.find("core_thickness_mm"), std::string::npos) << issue.format();
    }
}

TEST(PanelInput, FoamSceneInProcess) {
    const auto input =
        loadPanelInput(foamFixture("foam_40ppi_0p5in.json"), foamPanelInputKind(), FlagOverlay{});
    const auto result = buildFoamScene(input, {{"tool", "test"}});
    EXPECT_NO_THROW(hvi::io::validateAgainstSchema(result.scene, "scene", "scene"));
    EXPECT_EQ(result.scene["summary"]["layer_count"], 9);
    // Mass rule: to 1e-9 relative (brief).
    EXPECT_TRUE(
        near("areal mass", result.scene["summary"]["reduced_core_areal_mass_g_cm2"].get<double>(),
             result.scene["summary"]["real_core_areal_mass_g_cm2"].get<double>(), 0.0, 1e-9));
    // 9 layers and the rear wall are FE.
    EXPECT_EQ(result.feRectangles.size(), 10u);
    EXPECT_TRUE(result.warnings.empty());
    EXPECT_FALSE(result.report.empty());
}

TEST(PanelInput, SegmentLayersAreNamedPerSegment) {
    CLI::App app;
    FlagOverlay overlay;
    overlay.addString(app, "--model", "/reduction/model", "model", {"disks", "segments"});
    overlay.addNumber(app, "--segment-length-mm", "/reduction/segment_length_mm", "L");
    app.parse(std::vector<std::string>{"2", "--segment-length-mm", "segments", "--model"});
    const auto input =
        loadPanelInput(foamFixture("foam_10ppi_0p5in.json"), foamPanelInputKind(), overlay);
    const auto result = buildFoamScene(input, json::object());
    EXPECT_NO_THROW(hvi::io::validateAgainstSchema(result.scene, "scene", "scene"));
    EXPECT_EQ(result.scene["summary"]["layer_count"], 2);
    bool sawSegment = false;
    for (const auto& body : result.scene["bodies"]) {
        if (body["role"] == "core_layer") {
            EXPECT_NE(body["name"].get<std::string>().find("core_layer_0"), std::string::npos);
            EXPECT_NE(body["name"].get<std::string>().find("_seg_"), std::string::npos);
            sawSegment = true;
        }
    }
    EXPECT_TRUE(sawSegment);
    // Segments keep each layer's areal mass.
    EXPECT_TRUE(
        near("areal mass", result.scene["summary"]["reduced_core_areal_mass_g_cm2"].get<double>(),
             result.scene["summary"]["real_core_areal_mass_g_cm2"].get<double>(), 0.0, 1e-9));
}

TEST(PanelInput, HoneycombSceneInProcess) {
    const auto input = loadPanelInput(honeycombFixture("honeycomb_HITF04150.json"),
                                      honeycombPanelInputKind(), FlagOverlay{});
    const auto result = buildHoneycombScene(input, json::object());
    EXPECT_NO_THROW(hvi::io::validateAgainstSchema(result.scene, "scene", "scene"));
    EXPECT_EQ(result.scene["summary"]["ring_count"], 8);
    EXPECT_LT(result.scene["summary"]["core_areal_mass_ratio"].get<double>(), 1.0);
}
