#include "app/PanelInput.hpp"

#include "app/MaterialTable.hpp"
#include "ble/BleMaterials.hpp"
#include "geometry/InputChecks.hpp"
#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace hvi::app {

using nlohmann::json;

namespace {

const std::string kFacesheet = "/panel/facesheet_mm";
const std::string kFront = "/panel/front_facesheet_mm";
const std::string kRear = "/panel/rear_facesheet_mm";
const std::string kCore = "/panel/core_thickness_mm";
const std::string kSingleWall = "single_wall";

bool isSizingFile(const json& document) {
    if (!document.is_object()) {
        return false;
    }
    auto it = document.find("provenance");
    return it != document.end() && it->is_object() && it->value("tool", json()) == "ble-size";
}

/// Step 2 of the header: the tool's document from a ble-size sizing.json.
json fromSizing(const json& sizing, const std::string& file, const PanelInputKind& kind,
                std::vector<std::string>& notes) {
    std::vector<InputIssue> issues;
    json out = json::object();
    if (sizing.contains("id") && sizing["id"].is_string()) {
        out["id"] = sizing["id"];
    }
    if (sizing.contains("description") && sizing["description"].is_string()) {
        out["description"] = sizing["description"];
    }
    for (const char* block : {"threat", "panel"}) {
        if (!sizing.contains(block) || !sizing[block].is_object()) {
            issues.push_back({file, std::string("/") + block,
                              sizing.contains(block) ? "is not an object"
                                                     : "missing from the ble-size sizing file",
                              std::string("the ") + block +
                                  " block ble-size writes (it writes a panel block for "
                                  "foam_sandwich, whipple and single_wall shields)"});
        }
    }
    if (!issues.empty()) {
        throw InputError(std::move(issues));
    }

    json threat = sizing["threat"];
    if (threat.contains("angle_deg")) {
        const json& angle = threat["angle_deg"];
        if (!angle.is_number() || angle.get<double>() != 0.0) {
            issues.push_back({file, "/threat/angle_deg",
                              "is " + io::jsonText(angle) +
                                  ": a 2D axisymmetric scene holds only a normal impact",
                              "0 (impact along the panel normal); size oblique impacts with "
                              "ble-size only"});
        }
        threat.erase("angle_deg");
    }
    threat.erase("normal_velocity_km_s"); // derived by ble-size from speed and angle
    const auto* projectileMaterial =
        ble::findBleMaterial(threat.value("material", std::string("Al6061-T6")));
    if (threat.contains("density_g_cm3") && projectileMaterial &&
        std::fabs(threat["density_g_cm3"].get<double>() - projectileMaterial->densityGCm3) <=
            1e-9 * projectileMaterial->densityGCm3) {
        threat.erase("density_g_cm3"); // the material's own density: nothing to say
    }
    if (threat.contains("density_g_cm3")) {
        notes.push_back("threat density_g_cm3 = " + io::jsonText(threat["density_g_cm3"]) + " in " +
                        file +
                        " is not carried into the scene: hvi-run takes the projectile density "
                        "from its material ('" +
                        threat.value("material", std::string("Al6061-T6")) + "')");
        threat.erase("density_g_cm3");
    }
    out["threat"] = threat;

    json panel = sizing["panel"];
    const json type = panel.value("type", json());
    const auto& types = kind.sizingPanelTypes;
    const bool known = type.is_string() && std::find(types.begin(), types.end(),
                                                     type.get<std::string>()) != types.end();
    if (!known) {
        std::string expected;
        for (const auto& t : types) {
            expected += (expected.empty() ? "\"" : " or \"") + t + "\"";
        }
        issues.push_back({file, "/panel/type",
                          type.is_null() ? "required key is missing" : "is " + io::jsonText(type),
                          expected + " (" + kind.otherTypesHint + ")"});
    }
    if (types.size() == 1) {
        panel.erase("type"); // the tool's only type, its schema's default
    }
    for (const auto& key : kind.sizingPanelDrops) {
        panel.erase(key);
    }
    for (const auto& [from, to] : kind.sizingPanelRenames) {
        if (panel.contains(from)) {
            if (!panel.contains(to)) {
                panel[to] = panel[from];
            }
            panel.erase(from);
        }
    }
    out["panel"] = panel;
    if (!issues.empty()) {
        throw InputError(std::move(issues));
    }
    return out;
}

/// A file's facesheet_mm stands for both sides; a flag for one side replaces it for that
/// side only, so split it before the flags are applied.
void splitFacesheetForFlags(json& document, const FlagOverlay& flags) {
    if (!(flags.given(kFront) || flags.given(kRear)) || !document.is_object() ||
        !document.contains("panel") || !document["panel"].is_object()) {
        return;
    }
    json& panel = document["panel"];
    if (!panel.contains("facesheet_mm")) {
        return;
    }
    for (const char* side : {"front_facesheet_mm", "rear_facesheet_mm"}) {
        if (!panel.contains(side)) {
            panel[side] = panel["facesheet_mm"];
        }
    }
    panel.erase("facesheet_mm");
}

/// A single wall is the rear facesheet alone: facesheet_mm stands for it, and nothing in
/// front of it may be given.
template <typename Add>
void checkSingleWall(json& panel, const Add& add) {
    if (panel.contains("facesheet_mm") && panel.contains("rear_facesheet_mm")) {
        add(kFacesheet, "given together with rear_facesheet_mm",
            "the wall's thickness once: rear_facesheet_mm (or facesheet_mm)");
    } else if (panel.contains("facesheet_mm")) {
        panel["rear_facesheet_mm"] = panel["facesheet_mm"];
        panel.erase("facesheet_mm");
    } else if (!panel.contains("rear_facesheet_mm")) {
        add(kRear, "required key is missing",
            "the single wall's thickness [mm], > 0 (or facesheet_mm)");
    }
    for (const char* key :
         {"front_facesheet_mm", "core_thickness_mm", "front_facesheet_material"}) {
        if (panel.contains(key)) {
            add(std::string("/panel/") + key, "is given for a single wall (it has no bumper)",
                "no bumper or gap keys with panel type single_wall, or type whipple");
        }
    }
}

/// Step 5: facesheets, core thickness, materials.
void checkAndNormalise(json& resolved, const PanelInputKind& kind, const InputOrigin& origin) {
    std::vector<InputIssue> issues;
    auto add = [&](const std::string& pointer, std::string problem, std::string expected) {
        issues.push_back(
            {origin.labelOf(pointer), pointer, std::move(problem), std::move(expected)});
    };
    json& panel = resolved["panel"];
    const bool both = panel.contains("facesheet_mm");
    const bool singleWall = panel.value("type", "") == kSingleWall;
    if (singleWall) {
        checkSingleWall(panel, add);
    } else if (both &&
               (panel.contains("front_facesheet_mm") || panel.contains("rear_facesheet_mm"))) {
        const std::string other = panel.contains("front_facesheet_mm") ? kFront : kRear;
        add(kFacesheet, "given together with " + other.substr(7),
            "either facesheet_mm (both facesheets) or front_facesheet_mm and rear_facesheet_mm, "
            "not both");
    } else if (both) {
        panel["front_facesheet_mm"] = panel["facesheet_mm"];
        panel["rear_facesheet_mm"] = panel["facesheet_mm"];
        panel.erase("facesheet_mm");
    } else {
        if (!panel.contains("front_facesheet_mm")) {
            add(kFront, "required key is missing",
                "front (impact-side) facesheet thickness [mm], > 0 (or facesheet_mm for both)");
        }
        if (!panel.contains("rear_facesheet_mm")) {
            add(kRear, "required key is missing",
                "rear facesheet thickness [mm], > 0 (or facesheet_mm for both)");
        }
    }
    if (!singleWall && !panel.contains("core_thickness_mm")) {
        add(kCore, "required key is missing",
            "the gap between the facesheets [mm], > 0 (or panel type single_wall for a plate "
            "without a bumper)");
    }
    // A Whipple's gap may be shorter than its plates are thick; a sandwich's core may not.
    if (issues.empty() && !singleWall && panel.value("type", "") != "whipple") {
        const double front = panel["front_facesheet_mm"].get<double>();
        const double rear = panel["rear_facesheet_mm"].get<double>();
        const double core = panel["core_thickness_mm"].get<double>();
        if (!(core > front + rear)) {
            add("/panel/core_thickness_mm",
                "is " + geometry::formatNumber(core) +
                    " mm, not more than the two facesheets together (" +
                    geometry::formatNumber(front + rear) + " mm)",
                "core thickness between the facesheets [mm] > front_facesheet_mm + "
                "rear_facesheet_mm; a thinner core is not a sandwich panel: check the units");
        }
    }
    for (const auto& pointer : kind.materialPointers) {
        const json::json_pointer ptr(pointer);
        if (!resolved.contains(ptr)) {
            continue;
        }
        const std::string name = resolved.at(ptr).get<std::string>();
        if (!materialDensityGCm3(name)) {
            add(pointer, "unknown material '" + name + "'", "one of: " + materialNameList());
        }
    }
    if (!issues.empty()) {
        throw InputError(std::move(issues));
    }
}

} // namespace

double PanelInput::number(const std::string& pointer) const {
    const json::json_pointer ptr(pointer);
    return resolved.contains(ptr) ? resolved.at(ptr).get<double>() : geometry::kMissing;
}

std::string PanelInput::text(const std::string& pointer, const std::string& fallback) const {
    const json::json_pointer ptr(pointer);
    return resolved.contains(ptr) ? resolved.at(ptr).get<std::string>() : fallback;
}

geometry::ThreatSpec PanelInput::threat() const {
    geometry::ThreatSpec threat;
    threat.diameterMm = number("/threat/diameter_mm");
    threat.velocityKmS = number("/threat/velocity_km_s");
    threat.material = text("/threat/material", threat.material);
    return threat;
}

geometry::PanelFrame PanelInput::frame() const {
    geometry::PanelFrame frame;
    frame.bumper = text("/panel/type") != kSingleWall;
    frame.frontFacesheetMm = number(kFront);
    frame.coreThicknessMm = number("/panel/core_thickness_mm");
    frame.rearFacesheetMm = number(kRear);
    frame.facesheetMaterial = text("/panel/material", frame.facesheetMaterial);
    frame.frontFacesheetMaterial = text("/panel/front_facesheet_material", frame.facesheetMaterial);
    frame.rearFacesheetMaterial = text("/panel/rear_facesheet_material", frame.facesheetMaterial);
    return frame;
}

geometry::SceneNumerics PanelInput::numerics() const {
    geometry::SceneNumerics numerics;
    numerics.particleSpacingMm = number("/numerics/particle_spacing_mm");
    numerics.erosionFactor = number("/numerics/erosion_factor");
    numerics.coreDiscretization =
        geometry::parseDiscretization(text("/numerics/core_discretization", "fe"))
            .value_or(geometry::Discretization::Fe);
    numerics.rearWallDiscretization =
        geometry::parseDiscretization(text("/numerics/rear_wall_discretization", "fe"))
            .value_or(geometry::Discretization::Fe);
    numerics.domainRadiusMm = number("/numerics/domain_radius_mm");
    numerics.endTimeUs = number("/numerics/end_time_us");
    return numerics;
}

PanelInput loadPanelInput(const std::string& inputFile, const PanelInputKind& kind,
                          const FlagOverlay& flags) {
    PanelInput input;
    input.inputFile = inputFile;
    const std::string label = inputFile.empty() ? std::string(kFlagsLabel) : inputFile;
    input.origin = InputOrigin(label, flags.givenPointers());

    json document = inputFile.empty() ? json::object() : io::readJsonFile(inputFile);
    if (!document.is_object()) {
        throw InputError(label, "", "is " + std::string(document.type_name()) + ", not an object",
                         "a JSON object (schema " + kind.schemaName + ")");
    }
    if (isSizingFile(document)) {
        input.fromSizing = true;
        document = fromSizing(document, label, kind, input.notes);
    }
    splitFacesheetForFlags(document, flags);
    flags.applyTo(document);

    try {
        // The tool refuses NaN and infinite flags as it parses them (tool::FiniteFlags);
        // this check covers callers that parse flags without the tool, as tests do.
        io::requireFiniteNumbers(document, label);
        io::validateAgainstSchema(document, kind.schemaName, label);
    } catch (const InputError& e) {
        throw input.origin.relabel(e);
    }
    input.resolved = io::withSchemaDefaults(document, kind.schemaName);
    if (!input.resolved.contains("id")) {
        const std::string stem = std::filesystem::path(inputFile).stem().string();
        input.resolved["id"] =
            inputFile.empty() || inputFile == "-" || stem.empty() ? kind.defaultId : stem;
    }
    // The rear wall follows the core unless told otherwise: --core-discretization sph alone
    // gives the all-SPH scene hvi-run can run before its FE solver exists.
    json& numerics = input.resolved["numerics"];
    if (!numerics.contains("rear_wall_discretization")) {
        numerics["rear_wall_discretization"] = numerics.value("core_discretization", "fe");
    }
    checkAndNormalise(input.resolved, kind, input.origin);
    return input;
}

} // namespace hvi::app
