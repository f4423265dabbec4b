#include "app/Hcomb2RingsTool.hpp"

#include "app/MaterialTable.hpp"
#include "core/Units.hpp"
#include "geometry/HoneycombRings.hpp"
#include "geometry/InputChecks.hpp"
#include "geometry/SceneBuilder.hpp"

#include <algorithm>

namespace hvi::app {

using geometry::formatNumber;
using nlohmann::json;

namespace {

/// Where honeycomb_panel.json holds each key of geometry::HoneycombCoreSpec.
const std::vector<KeyLocation>& honeycombKeys() {
    static const std::vector<KeyLocation> keys = {
        {"core_thickness_mm", "/panel/core_thickness_mm"},
        {"cell_size_mm", "/panel/cell_size_mm"},
        {"foil_thickness_mm", "/panel/foil_thickness_mm"},
        {"foil_density_g_cm3", "/panel/foil_material"},
        {"double_wall_fraction", "/panel/double_wall_fraction"},
        {"impact_site", "/panel/impact_site"},
        {"impact_offset_x_mm", "/panel/impact_offset_x_mm"},
        {"impact_offset_y_mm", "/panel/impact_offset_y_mm"},
        {"ring_direction", "/panel/direction"},
        {"ring_angle_deg", "/panel/ring_angle_deg"},
        {"domain_radius_mm", "/numerics/domain_radius_mm"},
        {"particle_spacing_mm", "/numerics/particle_spacing_mm"},
    };
    return keys;
}

} // namespace

PanelInputKind honeycombPanelInputKind() {
    PanelInputKind kind;
    kind.schemaName = "honeycomb_panel";
    kind.sizingPanelTypes = {"honeycomb_sandwich"};
    kind.otherTypesHint = "hcomb2rings reads honeycomb panels; foam2layers reads foam_sandwich, "
                           "whipple and single_wall";
    kind.defaultId = "honeycomb_panel";
    kind.sizingPanelDrops = {"core_thickness_source", "equation", "rear_wall_yield_ksi",
                             "rear_wall_yield_MPa"};
    kind.sizingPanelRenames = {{"facesheet_material", "material"}};
    kind.materialPointers = {"/threat/material", "/panel/material", "/panel/foil_material",
                             "/panel/front_facesheet_material", "/panel/rear_facesheet_material"};
    return kind;
}

SceneResult buildHoneycombScene(const PanelInput& input, const json& provenance) {
    geometry::SceneBuilder builder(input.threat(), input.frame(), input.numerics());
    const geometry::PanelFrame frame = builder.frame();
    const std::string foilMaterial = input.text("/panel/foil_material", frame.facesheetMaterial);
    const double foilDensity = materialDensityGCm3(foilMaterial).value_or(geometry::kMissing);
    auto densityOf = [](const std::string& material) {
        return materialDensityGCm3(material).value_or(geometry::kMissing);
    };

    geometry::HoneycombCoreSpec spec;
    spec.coreThicknessMm = frame.coreThicknessMm;
    spec.cellSizeMm = input.number("/panel/cell_size_mm");
    spec.foilThicknessMm = input.number("/panel/foil_thickness_mm");
    spec.foilDensityGCm3 = foilDensity;
    spec.domainRadiusMm = builder.domainRadiusMm();
    spec.doubleWallFraction = input.number("/panel/double_wall_fraction");
    spec.impactSite = geometry::parseImpactSite(input.text("/panel/impact_site", "cell_centre"))
                          .value_or(geometry::ImpactSite::CellCentre);
    spec.impactOffsetXMm = input.number("/panel/impact_offset_x_mm");
    spec.impactOffsetYMm = input.number("/panel/impact_offset_y_mm");
    spec.direction = geometry::parseRingDirection(input.text("/panel/direction", "apothem"))
                         .value_or(geometry::RingDirection::Apothem);
    spec.ringAngleDeg = input.number("/panel/ring_angle_deg");
    spec.particleSpacingMm = builder.numerics().particleSpacingMm;

    geometry::HoneycombRings rings;
    try {
        rings = geometry::buildHoneycombRings(spec, input.origin.file(), "");
    } catch (const InputError& e) {
        throw input.origin.relabel(e, honeycombKeys());
    }

    json radii = json::array();
    json thicknesses = json::array();
    for (std::size_t i = 0; i < rings.rings.size(); ++i) {
        const auto& ring = rings.rings[i];
        builder.addCoreBody(geometry::indexedBodyName("core_ring", i + 1, rings.rings.size()),
                            "core_ring", foilMaterial, ring.zFrontMm, ring.zBackMm - ring.zFrontMm,
                            ring.innerRadiusMm, ring.outerRadiusMm);
        radii.push_back(ring.radiusMm);
        thicknesses.push_back(ring.thicknessMm);
    }

    SceneResult result;
    for (const auto& warning : rings.warnings) {
        result.warnings.push_back(warning.message);
    }
    for (const auto& warning : builder.warnings()) {
        result.warnings.push_back(warning.message);
    }

    const double facesheetArealGCm2 =
        units::mmToCm(densityOf(frame.frontFacesheetMaterial) * frame.frontFacesheetMm +
                      densityOf(frame.rearFacesheetMaterial) * frame.rearFacesheetMm);
    const double relativeDifference = rings.massRatio - 1.0;
    json summary = {
        {"core", "honeycomb"},
        {"input_kind", input.fromSizing ? "ble-size sizing" : "honeycomb_panel"},
        {"core_thickness_mm", frame.coreThicknessMm},
        {"cell_size_mm", spec.cellSizeMm},
        {"foil_thickness_mm", spec.foilThicknessMm},
        {"foil_material", foilMaterial},
        {"double_wall_fraction", spec.doubleWallFraction},
        {"impact_site", geometry::toString(spec.impactSite)},
        {"impact_x_mm", rings.impactXMm},
        {"impact_y_mm", rings.impactYMm},
        {"direction", geometry::toString(rings.direction)},
        {"direction_angle_deg", rings.angleDeg},
        {"ring_count", rings.rings.size()},
        {"ring_height_mm", frame.coreThicknessMm},
        {"ring_radii_mm", radii},
        {"ring_thicknesses_mm", thicknesses},
        {"relative_density", rings.relativeDensity},
        {"core_density_g_cm3", rings.coreDensityGCm3},
        {"real_core_areal_mass_g_cm2", rings.realArealMassGCm2},
        {"reduced_core_areal_mass_g_cm2", rings.reducedArealMassGCm2},
        {"core_areal_mass_ratio", rings.massRatio},
        {"core_areal_mass_relative_difference", relativeDifference},
        {"core_areal_mass_note", "the rings keep only the walls a ray from the impact point "
                                 "crosses; walls along the radial direction are dropped, so "
                                 "the reduced core is lighter than the real one by design"},
        {"real_panel_areal_mass_g_cm2", facesheetArealGCm2 + rings.realArealMassGCm2},
        {"reduced_panel_areal_mass_g_cm2", facesheetArealGCm2 + rings.reducedArealMassGCm2},
        {"warnings", result.warnings},
    };

    const geometry::ThreatSpec threat = input.threat();
    const std::string description =
        "Honeycomb-core sandwich panel: " + formatNumber(frame.frontFacesheetMm) + " / " +
        formatNumber(frame.coreThicknessMm) + " / " + formatNumber(frame.rearFacesheetMm) +
        " mm, " + formatNumber(spec.cellSizeMm) + " mm cells of " +
        formatNumber(spec.foilThicknessMm) + " mm " + foilMaterial + " foil reduced to " +
        std::to_string(rings.rings.size()) + " rings (" +
        std::string(geometry::toString(rings.direction)) + " from " +
        std::string(geometry::toString(spec.impactSite)) + "); " + formatNumber(threat.diameterMm) +
        " mm " + threat.material + " sphere at " + formatNumber(threat.velocityKmS) + " km/s";
    result.scene = builder.sceneJson(input.id(), description, summary, provenance);
    result.feRectangles = builder.feRectangles();

    std::string radiiText;
    for (std::size_t i = 0; i < rings.rings.size(); ++i) {
        if (i == 4 && rings.rings.size() > 6) {
            radiiText += ", ...";
            break;
        }
        radiiText += (i ? ", " : "") + formatNumber(rings.rings[i].radiusMm);
    }
    const auto [thinnest, thickest] = std::minmax_element(
        rings.rings.begin(), rings.rings.end(),
        [](const auto& a, const auto& b) { return a.thicknessMm < b.thicknessMm; });
    result.report = {
        input.id() + ": honeycomb core " + formatNumber(frame.coreThicknessMm) + " mm, " +
            formatNumber(spec.cellSizeMm) + " mm cells, foil " +
            formatNumber(spec.foilThicknessMm) + " mm -> " + std::to_string(rings.rings.size()) +
            " rings (" + std::string(geometry::toString(rings.direction)) + " from " +
            std::string(geometry::toString(spec.impactSite)) + ")",
        "ring radii " + radiiText + " mm; thickness " + formatNumber(thinnest->thicknessMm) +
            (thinnest->thicknessMm == thickest->thicknessMm
                 ? ""
                 : " to " + formatNumber(thickest->thicknessMm)) +
            " mm, height " + formatNumber(frame.coreThicknessMm) + " mm",
        "core areal mass: real " + formatNumber(rings.realArealMassGCm2) + " g/cm2, reduced " +
            formatNumber(rings.reducedArealMassGCm2) + " g/cm2 (" +
            formatPercent(relativeDifference) + ": radial walls dropped by design)",
    };
    for (const auto& line : sharedReport(builder)) {
        result.report.push_back(line);
    }
    return result;
}

Hcomb2RingsTool::Hcomb2RingsTool()
    : SceneWriterTool("hcomb2rings",
                      "Honeycomb-core sandwich panel -> 2D axisymmetric impact scene for hvi-run: "
                      "the hexagonal core becomes concentric rings where a ray from the impact "
                      "point crosses the cell walls",
                      honeycombPanelInputKind()) {}

void Hcomb2RingsTool::addCoreOptions(CLI::App& app, FlagOverlay& flags) {
    flags.addNumber(app, "--cell-size-mm", "/panel/cell_size_mm",
                    "Hexagonal cell size across flats [mm], > 0");
    flags.addNumber(app, "--foil-thickness-mm", "/panel/foil_thickness_mm",
                    "Cell-wall foil thickness [mm], 0 < value < cell size / 2");
    flags.addString(app, "--foil-material", "/panel/foil_material",
                    "Foil material name (default: the facesheet material)");
    flags.addNumber(app, "--double-wall-fraction", "/panel/double_wall_fraction",
                    "Fraction of ribbon walls that are double foil [-], 0 <= value <= 1 "
                    "(default 1)");
    flags.addString(app, "--impact-site", "/panel/impact_site",
                    "Where the shot line meets the core (default cell_centre)",
                    {"cell_centre", "cell_wall", "offset"});
    flags.addNumber(app, "--impact-offset-x-mm", "/panel/impact_offset_x_mm",
                    "Impact point from the cell centre along W [mm] (with --impact-site offset)");
    flags.addNumber(app, "--impact-offset-y-mm", "/panel/impact_offset_y_mm",
                    "Impact point from the cell centre along L [mm] (with --impact-site offset)");
    flags.addString(app, "--direction", "/panel/direction",
                    "Ray giving the rings: apothem (0 deg, default), vertex (30 deg), custom "
                    "(--ring-angle-deg)",
                    {"apothem", "vertex", "custom"});
    flags.addNumber(app, "--ring-angle-deg", "/panel/ring_angle_deg",
                    "Ray direction from the W axis [deg] (with --direction custom)");
}

} // namespace hvi::app
