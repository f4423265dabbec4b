// SceneBuilder: the frame (projectile, bumper, core shift, rear wall), the domain-radius and
// end-time rules against hand values, schema validity of the scene, FE rectangles, warnings.
#include "Tolerance.hpp"
#include "geometry/SceneBuilder.hpp"
#include "io/JsonInput.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <stdexcept>
#include <string>

using hvi::geometry::Discretization;
using hvi::geometry::domainRadiusRule;
using hvi::geometry::endTimeRule;
using hvi::geometry::indexedBodyName;
using hvi::geometry::PanelFrame;
using hvi::geometry::SceneBody;
using hvi::geometry::SceneBuilder;
using hvi::geometry::SceneNumerics;
using hvi::geometry::ThreatSpec;
using hvi::test::near;
using nlohmann::json;

namespace {

// Positions are sums of a few mm-sized terms: 1e-12 mm absolute is rounding.
constexpr double kPosition = 1e-12;

ThreatSpec hitf04151Threat() {
    return {3.6, 6.76, "Al6061-T6"};
}

PanelFrame hitf04151Frame() {
    return {0.254, 50.8, 0.254, "Al6061-T6"};
}

double tan17() {
    return std::tan(17.0 * std::numbers::pi / 180.0);
}

} // namespace

// 2 x (1.8 + 51.054 tan 17°) = 2 x 17.4088 = 34.8175 -> 35 mm; 5 d = 18 mm.
TEST(SceneBuilder, DomainRadiusRuleHitf04151) {
    const auto rule = domainRadiusRule(hitf04151Threat(), hitf04151Frame());
    const double handFootprint = 1.8 + 51.054 * tan17();
    EXPECT_TRUE(near("hand footprint", handFootprint, 17.4088, 1e-4, 0.0));
    EXPECT_EQ(rule.value, std::ceil(2.0 * handFootprint));
    EXPECT_EQ(rule.value, 35.0);
    EXPECT_NE(rule.reason.find("17 deg"), std::string::npos) << rule.reason;
    EXPECT_NE(rule.reason.find("R = 35 mm"), std::string::npos) << rule.reason;
}

// A thin core: 2 x (1.5 + 2.1 tan 17°) = 4.28 mm < 5 d = 15 mm: the floor decides.
TEST(SceneBuilder, DomainRadiusFloorForThinCores) {
    const auto rule = domainRadiusRule({3.0, 7.0, "Al6061-T6"}, {0.1, 2.0, 0.1, "Al6061-T6"});
    EXPECT_EQ(rule.value, 15.0);
}

// L = 0.015 + 0.254 + 50.8 + 0.254 = 51.323 mm; 10 x 51.323 / 6.76 + 10 = 85.92 -> 86 us.
TEST(SceneBuilder, EndTimeRuleHitf04151) {
    const auto rule = endTimeRule(hitf04151Threat(), hitf04151Frame(), 0.015);
    EXPECT_EQ(rule.value, std::ceil(10.0 * 51.323 / 6.76 + 10.0));
    EXPECT_EQ(rule.value, 86.0);
    EXPECT_NE(rule.reason.find("T = 86 us"), std::string::npos) << rule.reason;
}

TEST(SceneBuilder, GivenValuesOverrideTheRules) {
    SceneNumerics numerics;
    numerics.domainRadiusMm = 12.5;
    numerics.endTimeUs = 3.0;
    const SceneBuilder builder(hitf04151Threat(), hitf04151Frame(), numerics);
    EXPECT_EQ(builder.domainRadiusMm(), 12.5);
    EXPECT_EQ(builder.endTime().value, 3.0);
    EXPECT_NE(builder.domainRadius().reason.find("given"), std::string::npos);
}

TEST(SceneBuilder, FrameAndRoles) {
    SceneBuilder builder(hitf04151Threat(), hitf04151Frame(), SceneNumerics{});
    // A layer at 5.08 mm from the rear face of the front facesheet, 0.4 mm thick.
    builder.addCoreBody("core_layer_01", "core_layer", "Al6061-T6", 4.88, 0.4, 0.0, 35.0);
    const auto bodies = builder.bodies();
    ASSERT_EQ(bodies.size(), 4u);

    const SceneBody& projectile = bodies[0];
    EXPECT_EQ(projectile.role, "projectile");
    EXPECT_EQ(projectile.shape, SceneBody::Shape::Sphere);
    EXPECT_TRUE(near("projectile centre", projectile.centerZMm, -1.815, kPosition, 0.0));
    EXPECT_EQ(projectile.discretization, Discretization::Sph);
    EXPECT_EQ(projectile.velocityZKmS, 6.76);

    EXPECT_EQ(bodies[1].role, "bumper");
    EXPECT_EQ(bodies[1].discretization, Discretization::Sph);
    EXPECT_EQ(bodies[1].zFrontMm, 0.0);
    EXPECT_EQ(bodies[1].outerRadiusMm, 35.0);

    EXPECT_EQ(bodies[2].role, "core_layer");
    EXPECT_TRUE(
        near("core shifted by the front facesheet", bodies[2].zFrontMm, 5.134, kPosition, 0.0));
    EXPECT_EQ(bodies[2].discretization, Discretization::Fe);

    EXPECT_EQ(bodies[3].role, "rear_wall");
    EXPECT_TRUE(near("rear wall", bodies[3].zFrontMm, 51.054, kPosition, 0.0));
    EXPECT_EQ(bodies[3].discretization, Discretization::Fe);
    for (std::size_t i = 1; i < bodies.size(); ++i) {
        EXPECT_EQ(bodies[i].velocityZKmS, 0.0);
    }
}

TEST(SceneBuilder, SceneValidatesAgainstTheSceneSchema) {
    SceneBuilder builder(hitf04151Threat(), hitf04151Frame(), SceneNumerics{});
    builder.addCoreBody("core_ring_01", "core_ring", "Al6061-T6", 0.0, 50.8, 2.3, 2.4);
    const json scene = builder.sceneJson("case", "text", {{"ring_count", 1}}, {{"tool", "test"}});
    EXPECT_NO_THROW(hvi::io::validateAgainstSchema(scene, "scene", "scene"));
    EXPECT_EQ(scene["summary"]["ring_count"], 1);
    EXPECT_EQ(scene["summary"]["domain_radius_mm"].get<double>(), 35.0);
    EXPECT_FALSE(scene["summary"]["end_time_reason"].get<std::string>().empty());
    EXPECT_EQ(scene["domain"]["radius_reason"], scene["summary"]["domain_radius_reason"]);
    // Stop rules written out at the scene schema's defaults.
    EXPECT_EQ(scene["run"]["stop_no_new_penetration_us"].get<double>(), 0.25);
    EXPECT_EQ(scene["bodies"].size(), 4u);
}

TEST(SceneBuilder, FeRectanglesFollowTheDiscretization) {
    SceneNumerics numerics;
    numerics.particleSpacingMm = 0.02;
    SceneBuilder builder(hitf04151Threat(), hitf04151Frame(), numerics);
    builder.addCoreBody("core_layer_01", "core_layer", "Al6061-T6", 4.88, 0.4, 0.0, 35.0);
    auto rects = builder.feRectangles();
    ASSERT_EQ(rects.size(), 2u);
    EXPECT_EQ(rects[0].name, "core_layer_01");
    EXPECT_TRUE(near("z min", rects[0].zMinMm, 5.134, kPosition, 0.0));
    EXPECT_TRUE(near("z max", rects[0].zMaxMm, 5.534, kPosition, 0.0));
    EXPECT_EQ(rects[0].rMaxMm, 35.0);
    EXPECT_EQ(rects[0].elementSizeMm, 0.02);
    EXPECT_EQ(rects[1].name, "rear_facesheet");

    numerics.coreDiscretization = Discretization::Sph;
    numerics.rearWallDiscretization = Discretization::Sph;
    SceneBuilder allSph(hitf04151Threat(), hitf04151Frame(), numerics);
    allSph.addCoreBody("core_layer_01", "core_layer", "Al6061-T6", 4.88, 0.4, 0.0, 35.0);
    EXPECT_TRUE(allSph.feRectangles().empty());
}

TEST(SceneBuilder, WarnsAboutThinFacesheetsAndASmallDomain) {
    SceneNumerics numerics;
    numerics.particleSpacingMm = 0.1; // 0.254 mm facesheets need <= 0.0846667 mm
    numerics.domainRadiusMm = 10.0;   // inside the 17.4 mm footprint
    const SceneBuilder builder(hitf04151Threat(), hitf04151Frame(), numerics);
    std::string all;
    for (const auto& w : builder.warnings()) {
        all += w.message + "\n";
    }
    EXPECT_NE(all.find("front facesheet thickness 0.254 mm"), std::string::npos) << all;
    EXPECT_NE(all.find("0.0846667 mm"), std::string::npos) << all;
    EXPECT_NE(all.find("domain radius 10 mm is inside"), std::string::npos) << all;
    EXPECT_EQ(builder.warnings().size(), 3u) << all;

    const SceneBuilder calibrated(hitf04151Threat(), hitf04151Frame(), SceneNumerics{});
    EXPECT_TRUE(calibrated.warnings().empty());
}

TEST(SceneBuilder, WarnsAboutAProjectileFewSpacingsAcross) {
    SceneNumerics numerics;
    numerics.particleSpacingMm = 0.4; // the 3.6 mm sphere is 9 spacings across
    std::string all;
    for (const auto& w : SceneBuilder(hitf04151Threat(), hitf04151Frame(), numerics).warnings()) {
        all += w.message + "\n";
    }
    EXPECT_NE(all.find("projectile diameter 3.6 mm is 9 particle spacings across at 0.4 mm"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("spacing <= 0.36 mm"), std::string::npos) << all;
    numerics.particleSpacingMm = 0.36; // exactly 10 across: no warning about the projectile
    all.clear();
    for (const auto& w : SceneBuilder(hitf04151Threat(), hitf04151Frame(), numerics).warnings()) {
        all += w.message + "\n";
    }
    EXPECT_EQ(all.find("projectile"), std::string::npos) << all;
}

TEST(SceneBuilder, RejectsNonPhysicalSizes) {
    ThreatSpec threat = hitf04151Threat();
    threat.diameterMm = std::nan("");
    EXPECT_THROW(SceneBuilder(threat, hitf04151Frame(), SceneNumerics{}), std::invalid_argument);
    PanelFrame frame = hitf04151Frame();
    frame.rearFacesheetMm = 0.0;
    EXPECT_THROW(SceneBuilder(hitf04151Threat(), frame, SceneNumerics{}), std::invalid_argument);
    SceneBuilder builder(hitf04151Threat(), hitf04151Frame(), SceneNumerics{});
    EXPECT_THROW(builder.addCoreBody("x", "core_ring", "Al6061-T6", 0.0, 1.0, 3.0, 2.0),
                 std::invalid_argument);
}

TEST(SceneBuilder, IndexedNamesSortInOrder) {
    EXPECT_EQ(indexedBodyName("core_layer", 3, 9), "core_layer_03");
    EXPECT_EQ(indexedBodyName("core_layer", 7, 39), "core_layer_07");
    EXPECT_EQ(indexedBodyName("core_ring", 12, 150), "core_ring_012");
}
