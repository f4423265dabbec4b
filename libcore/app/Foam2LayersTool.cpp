#include "app/Foam2LayersTool.hpp"

#include "app/MaterialTable.hpp"
#include "core/Units.hpp"
#include "geometry/FoamLayerStack.hpp"
#include "geometry/InputChecks.hpp"
#include "geometry/SceneBuilder.hpp"

#include <algorithm>
#include <map>

namespace hvi::app {

using geometry::formatNumber;
using nlohmann::json;

namespace {

/// Each key of geometry::FoamCoreSpec, written once: where foam_panel.json holds it, the
/// flag that sets it (none for the keys the panel frame and the numerics give), and how it
/// reaches the spec. The order is the flags' order in --help.
struct FoamKey {
    const char* libraryKey; ///< its name in geometry::FoamCoreSpec's error messages
    const char* pointer;    ///< where foam_panel.json holds it
    const char* flags;      ///< foam2layers' flag(s), or nullptr
    const char* help;
    std::vector<std::string> choices;       ///< a text key's values, the default first
    double geometry::FoamCoreSpec::*number; ///< the member a number fills, or nullptr
};

const std::vector<FoamKey>& foamKeyTable() {
    using Spec = geometry::FoamCoreSpec;
    static const std::vector<FoamKey> keys = {
        {"standoff_mm", "/panel/core_thickness_mm", nullptr, "", {}, nullptr},
        {"relative_density_percent",
         "/panel/relative_density_percent",
         "--relative-density-percent",
         "Foam relative density [%], 0 < value < 100",
         {},
         &Spec::relativeDensityPercent},
        {"ppi", "/panel/ppi", "--ppi", "Foam pores per inch [1/in], > 0", {}, &Spec::ppi},
        {"material_density_g_cm3", "/panel/material", nullptr, "", {}, nullptr},
        {"domain_radius_mm", "/numerics/domain_radius_mm", nullptr, "", {}, nullptr},
        {"particle_spacing_mm", "/numerics/particle_spacing_mm", nullptr, "", {}, nullptr},
        {"ppi_factor",
         "/reduction/ppi_factor",
         "--effective-ppi-factor,--ppi-factor",
         "Effective PPI / real PPI [-], 0 < value <= 1 (default 0.5)",
         {},
         &Spec::ppiFactor},
        {"thickness_rule",
         "/reduction/layer_rule",
         "--layer-rule",
         "Layer thickness: mass (default, conserves the foam's areal mass), eq31 "
         "(source study's eq 31), ligament (--ligament-thickness-mm)",
         {"mass", "eq31", "ligament"},
         nullptr},
        {"ligament_thickness_mm",
         "/reduction/ligament_thickness_mm",
         "--ligament-thickness-mm",
         "Measured ligament thickness [mm], > 0 (with --layer-rule ligament)",
         {},
         &Spec::ligamentThicknessMm},
        {"layer_model",
         "/reduction/model",
         "--model",
         "Layers as full disks (default) or staggered flat segments",
         {"disks", "segments"},
         nullptr},
        {"segment_length_mm",
         "/reduction/segment_length_mm",
         "--segment-length-mm",
         "Radial length of one flat segment [mm], > 0 (with --model segments)",
         {},
         &Spec::segmentLengthMm},
        {"segment_gap_fraction",
         "/reduction/segment_gap_fraction",
         "--segment-gap-fraction",
         "Gap / (segment + gap) [-], 0 <= value < 1 (default 0.5)",
         {},
         &Spec::segmentGapFraction},
        {"segment_stagger_fraction",
         "/reduction/segment_stagger_fraction",
         "--segment-stagger-fraction",
         "Radial shift of even layers / segment period [-], 0 <= value < 1 (default 0.5)",
         {},
         &Spec::segmentStaggerFraction},
    };
    return keys;
}

/// Where foam_panel.json holds each key of geometry::FoamCoreSpec (to name it in errors).
const std::vector<KeyLocation>& foamKeys() {
    static const std::vector<KeyLocation> keys = [] {
        std::vector<KeyLocation> out;
        for (const auto& key : foamKeyTable()) {
            out.push_back({key.libraryKey, key.pointer});
        }
        return out;
    }();
    return keys;
}

/// A text key's value, or its default (its first choice).
std::string foamText(const PanelInput& input, const std::string& libraryKey) {
    for (const auto& key : foamKeyTable()) {
        if (libraryKey == key.libraryKey) {
            return input.text(key.pointer, key.choices.front());
        }
    }
    throw std::logic_error("no foam key " + libraryKey);
}

} // namespace

PanelInputKind foamPanelInputKind() {
    PanelInputKind kind;
    kind.schemaName = "foam_panel";
    kind.sizingPanelTypes = {"foam_sandwich", "whipple", "single_wall"};
    kind.otherTypesHint = "foam2layers reads foam panels, Whipple shields and single walls; "
                          "hcomb2rings reads honeycomb_sandwich";
    kind.defaultId = "foam_panel";
    kind.sizingPanelDrops = {"core_thickness_source", "rear_wall_yield_ksi", "rear_wall_yield_MPa"};
    kind.materialPointers = {"/threat/material", "/panel/material",
                             "/panel/front_facesheet_material", "/panel/rear_facesheet_material",
                             "/panel/core_material"};
    return kind;
}

namespace {

double densityOf(const std::string& material) {
    return materialDensityGCm3(material).value_or(geometry::kMissing);
}

/// The facesheets' areal mass [g/cm2].
double facesheetArealMassGCm2(const geometry::PanelFrame& frame) {
    return units::mmToCm(densityOf(frame.frontFacesheetMaterial) * frame.frontFacesheetMm +
                         densityOf(frame.rearFacesheetMaterial) * frame.rearFacesheetMm);
}

/// The keys one panel type requires and the others may not hold, all reported at once.
/// `coreless`: "whipple" or "single_wall", empty for a foam panel.
void checkPanelTypeKeys(const PanelInput& input, const std::string& coreless) {
    std::vector<InputIssue> issues;
    for (const char* key : {"relative_density_percent", "ppi", "core_material"}) {
        const std::string pointer = std::string("/panel/") + key;
        const bool given = input.resolved.contains(json::json_pointer(pointer));
        if (!coreless.empty() && given) {
            issues.push_back({input.origin.labelOf(pointer), pointer,
                              "is given for panel type " + coreless + ", which has no core",
                              "no foam keys with type " + coreless + ", or type foam_sandwich"});
        } else if (coreless.empty() && !given && std::string(key) != "core_material") {
            issues.push_back({input.origin.labelOf(pointer), pointer, "required key is missing",
                              std::string("the foam's ") +
                                  (std::string(key) == "ppi" ? "pores per inch [1/in], > 0"
                                                             : "relative density [%], 0..100") +
                                  " (or panel type whipple for a shield without a core)"});
        }
    }
    if (!issues.empty()) {
        throw InputError(std::move(issues));
    }
}

/// A Whipple shield (the panel frame with nothing between the facesheets) or a single wall
/// (the rear facesheet alone).
SceneResult buildCorelessScene(const PanelInput& input, const json& provenance) {
    geometry::SceneBuilder builder(input.threat(), input.frame(), input.numerics());
    const geometry::PanelFrame frame = builder.frame();
    SceneResult result;
    for (const auto& warning : builder.warnings()) {
        result.warnings.push_back(warning.message);
    }
    const geometry::ThreatSpec threat = input.threat();
    const std::string projectile = formatNumber(threat.diameterMm) + " mm " + threat.material +
                                   " sphere at " + formatNumber(threat.velocityKmS) + " km/s";
    const std::string wall =
        formatNumber(frame.rearFacesheetMm) + " mm " + frame.rearFacesheetMaterial;
    json summary = {
        {"core", "none"},
        {"shield", frame.bumper ? "whipple" : "single_wall"},
        {"input_kind", input.fromSizing ? "ble-size sizing" : "foam_panel"},
        {"panel_areal_mass_g_cm2", facesheetArealMassGCm2(frame)},
    };
    std::string description;
    if (frame.bumper) {
        summary["standoff_mm"] = frame.coreThicknessMm;
        summary["standoff_convention"] = "gap from the back of the bumper to the front of the "
                                         "rear wall (the NASA JSC Whipple equation's S)";
        description = "Whipple shield: " + formatNumber(frame.frontFacesheetMm) + " mm " +
                      frame.frontFacesheetMaterial + " bumper, " +
                      formatNumber(frame.coreThicknessMm) + " mm gap, " + wall + " rear wall; " +
                      projectile;
        result.report = {input.id() +
                         ": Whipple shield, no core: " + formatNumber(frame.frontFacesheetMm) +
                         " mm bumper, " + formatNumber(frame.coreThicknessMm) + " mm gap, " +
                         formatNumber(frame.rearFacesheetMm) + " mm rear wall"};
    } else {
        description = "Single wall: " + wall + " plate; " + projectile;
        result.report = {input.id() + ": single wall " + formatNumber(frame.rearFacesheetMm) +
                         " mm, no bumper"};
    }
    summary["warnings"] = result.warnings;
    result.scene = builder.sceneJson(input.id(), description, summary, provenance);
    result.feRectangles = builder.feRectangles();
    for (const auto& line : sharedReport(builder)) {
        result.report.push_back(line);
    }
    return result;
}

} // namespace

SceneResult buildFoamScene(const PanelInput& input, const json& provenance) {
    const std::string type = input.text("/panel/type", "foam_sandwich");
    const std::string coreless = type == "foam_sandwich" ? "" : type;
    checkPanelTypeKeys(input, coreless);
    if (!coreless.empty()) {
        return buildCorelessScene(input, provenance);
    }
    geometry::SceneBuilder builder(input.threat(), input.frame(), input.numerics());
    const geometry::PanelFrame frame = builder.frame();
    const std::string material = input.text("/panel/core_material", frame.facesheetMaterial);
    const double density = densityOf(material);

    geometry::FoamCoreSpec spec;
    spec.standoffMm = frame.coreThicknessMm;
    for (const auto& key : foamKeyTable()) {
        if (key.number) {
            spec.*key.number = input.number(key.pointer);
        }
    }
    spec.materialDensityGCm3 = density;
    spec.domainRadiusMm = builder.domainRadiusMm();
    spec.rule = geometry::parseFoamThicknessRule(foamText(input, "thickness_rule"))
                    .value_or(geometry::FoamThicknessRule::Mass);
    spec.model = geometry::parseFoamLayerModel(foamText(input, "layer_model"))
                     .value_or(geometry::FoamLayerModel::Disks);
    spec.particleSpacingMm = builder.numerics().particleSpacingMm;

    geometry::FoamLayerStack stack;
    try {
        stack = geometry::buildFoamLayerStack(spec, input.origin.file(), "");
    } catch (const InputError& e) {
        throw input.origin.relabel(e, foamKeys());
    }

    // Layer bodies: one per disk, or one per segment ("core_layer_03_seg_002").
    std::map<int, int> segmentsPerLayer;
    int largestSegment = 1;
    for (const auto& layer : stack.layers) {
        largestSegment = std::max(largestSegment, ++segmentsPerLayer[layer.layerIndex]);
    }
    int segment = 0;
    int previousLayer = 0;
    for (const auto& layer : stack.layers) {
        segment = layer.layerIndex == previousLayer ? segment + 1 : 1;
        previousLayer = layer.layerIndex;
        std::string name =
            geometry::indexedBodyName("core_layer", static_cast<std::size_t>(layer.layerIndex),
                                      static_cast<std::size_t>(stack.layerCount));
        if (stack.model == geometry::FoamLayerModel::Segments) {
            name = geometry::indexedBodyName(name + "_seg", static_cast<std::size_t>(segment),
                                             static_cast<std::size_t>(largestSegment));
        }
        builder.addCoreBody(name, "core_layer", material, layer.zFrontMm, layer.thicknessMm,
                            layer.innerRadiusMm, layer.outerRadiusMm);
    }

    SceneResult result;
    for (const auto& warning : stack.warnings) {
        result.warnings.push_back(warning.message);
    }
    for (const auto& warning : builder.warnings()) {
        result.warnings.push_back(warning.message);
    }

    const double facesheetArealGCm2 = facesheetArealMassGCm2(frame);
    const double relativeDifference = stack.reducedArealMassGCm2 / stack.realArealMassGCm2 - 1.0;
    json summary = {
        {"core", "foam"},
        {"input_kind", input.fromSizing ? "ble-size sizing" : "foam_panel"},
        {"core_thickness_mm", frame.coreThicknessMm},
        {"relative_density_percent", spec.relativeDensityPercent},
        {"ppi", spec.ppi},
        {"ppi_factor", spec.ppiFactor},
        {"effective_ppi", stack.effectivePpi},
        {"pores_exact", stack.poresExact},
        {"pore_count", stack.poreCount},
        {"layer_count", stack.layerCount},
        {"layer_bodies", stack.layers.size()},
        {"layer_rule", geometry::toString(stack.rule)},
        {"layer_model", geometry::toString(stack.model)},
        {"solid_thickness_mm", stack.solidThicknessMm},
        {"layer_thickness_mm", stack.layerThicknessMm},
        {"layer_spacing_mm", stack.layerSpacingMm},
        {"layer_positions", "centre-spaced: layer k's mid-plane at z = front facesheet + k x "
                            "layer_spacing_mm"},
        {"material_density_g_cm3", density},
        {"real_core_areal_mass_g_cm2", stack.realArealMassGCm2},
        {"reduced_core_areal_mass_g_cm2", stack.reducedArealMassGCm2},
        {"core_areal_mass_relative_difference", relativeDifference},
        {"real_panel_areal_mass_g_cm2", facesheetArealGCm2 + stack.realArealMassGCm2},
        {"reduced_panel_areal_mass_g_cm2", facesheetArealGCm2 + stack.reducedArealMassGCm2},
        {"warnings", result.warnings},
    };

    const geometry::ThreatSpec threat = input.threat();
    const std::string description =
        "Foam-core sandwich panel: " + formatNumber(frame.frontFacesheetMm) + " / " +
        formatNumber(frame.coreThicknessMm) + " / " + formatNumber(frame.rearFacesheetMm) +
        " mm, " + formatNumber(spec.relativeDensityPercent) + " % " + formatNumber(spec.ppi) +
        " PPI " + material + " foam reduced to " + std::to_string(stack.layerCount) + " layers (" +
        std::string(geometry::toString(stack.model)) + ", rule " +
        std::string(geometry::toString(stack.rule)) + "); " + formatNumber(threat.diameterMm) +
        " mm " + threat.material + " sphere at " + formatNumber(threat.velocityKmS) + " km/s";
    result.scene = builder.sceneJson(input.id(), description, summary, provenance);
    result.feRectangles = builder.feRectangles();

    result.report = {
        input.id() + ": foam core " + formatNumber(frame.coreThicknessMm) + " mm, " +
            formatNumber(spec.ppi) + " PPI x " + formatNumber(spec.ppiFactor) + " = " +
            formatNumber(stack.effectivePpi) + " effective PPI -> " +
            (stack.poresExact == static_cast<double>(stack.poreCount)
                 ? std::to_string(stack.poreCount) + " pores"
                 : formatNumber(stack.poresExact) + " pores, rounded up to " +
                       std::to_string(stack.poreCount)) +
            " -> " + std::to_string(stack.layerCount) + " layers (" +
            std::string(geometry::toString(stack.model)) + ", rule " +
            std::string(geometry::toString(stack.rule)) + ")",
        "layer thickness " + formatNumber(stack.layerThicknessMm) + " mm, spacing " +
            formatNumber(stack.layerSpacingMm) + " mm between mid-planes (gap " +
            formatNumber(stack.layerSpacingMm - stack.layerThicknessMm) + " mm)",
        "core areal mass: real " + formatNumber(stack.realArealMassGCm2) + " g/cm2, reduced " +
            formatNumber(stack.reducedArealMassGCm2) + " g/cm2 (" +
            formatPercent(relativeDifference) + ")",
    };
    for (const auto& line : sharedReport(builder)) {
        result.report.push_back(line);
    }
    return result;
}

Foam2LayersTool::Foam2LayersTool()
    : SceneWriterTool("foam2layers",
                      "Foam-core sandwich panel -> 2D axisymmetric impact scene for hvi-run: the "
                      "open-cell foam core becomes a mass-conserved stack of flat layers "
                      "(effective PPI = ppi_factor x PPI, pores rounded up, layers = pores - 1); "
                      "with --panel-type whipple, a Whipple shield (the same frame, no core); "
                      "with --panel-type single_wall, a plate alone (--rear-facesheet-mm)",
                      foamPanelInputKind()) {}

void Foam2LayersTool::addCoreOptions(CLI::App& app, FlagOverlay& flags) {
    flags.addString(app, "--panel-type", "/panel/type",
                    "foam_sandwich (default); whipple: no core, the facesheets are the bumper "
                    "and the rear wall and --standoff-mm the gap between them; single_wall: the "
                    "rear facesheet alone, struck directly",
                    {"foam_sandwich", "whipple", "single_wall"});
    flags.addString(app, "--core-material", "/panel/core_material",
                    "Foam ligament material (default: --material)");
    for (const auto& key : foamKeyTable()) {
        if (!key.flags) {
            continue;
        }
        if (key.choices.empty()) {
            flags.addNumber(app, key.flags, key.pointer, key.help);
        } else {
            flags.addString(app, key.flags, key.pointer, key.help, key.choices);
        }
    }
}

} // namespace hvi::app
