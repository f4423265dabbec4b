#include "validation/CaseInputs.hpp"

namespace hvi::validation {

using nlohmann::json;

std::string sceneWriterOf(const Case& c) {
    return c.shield == Shield::Honeycomb ? "hcomb2rings" : "foam2layers";
}

namespace {

std::string describe(const Case& c) {
    std::string text = "Validation case " + c.id + " (" + c.set + ", test result " + c.result +
                       "; " + c.source + ")";
    for (const auto& a : c.assumptions) {
        text += "; " + a;
    }
    return text;
}

} // namespace

json panelInput(const Case& c) {
    json panel = {{"front_facesheet_mm", c.front.thicknessMm},
                  {"rear_facesheet_mm", c.rear.thicknessMm},
                  {"core_thickness_mm", c.gapMm},
                  {"material", c.front.material},
                  {"front_facesheet_material", c.front.material},
                  {"rear_facesheet_material", c.rear.material}};
    switch (c.shield) {
    case Shield::Whipple:
        panel["type"] = "whipple";
        break;
    case Shield::Foam:
        panel["relative_density_percent"] = c.relativeDensityPercent;
        panel["ppi"] = c.ppi;
        panel["core_material"] = c.coreMaterial;
        break;
    case Shield::Honeycomb:
        panel["cell_size_mm"] = c.cellSizeMm;
        panel["foil_thickness_mm"] = c.foilThicknessMm;
        panel["foil_material"] = c.coreMaterial;
        break;
    }
    return {{"id", c.id},
            {"description", describe(c)},
            {"threat",
             {{"diameter_mm", c.diameterMm},
              {"velocity_km_s", c.velocityKmS},
              {"material", c.projectileMaterial}}},
            {"panel", panel}};
}

json bleConstraints(const Case& c) {
    json shield;
    switch (c.shield) {
    case Shield::Whipple:
        shield = {{"type", "whipple"},
                  {"bumper_mm", c.front.thicknessMm},
                  {"rear_wall_mm", c.rear.thicknessMm},
                  {"standoff_mm", c.gapMm},
                  {"bumper_material", c.front.material},
                  {"rear_wall_material", c.rear.material}};
        if (c.rearYieldKsi) {
            shield["rear_wall_yield_ksi"] = *c.rearYieldKsi;
        }
        break;
    case Shield::Foam:
        shield = {{"type", "foam_sandwich"},
                  {"front_facesheet_mm", c.front.thicknessMm},
                  {"rear_facesheet_mm", c.rear.thicknessMm},
                  {"core_thickness_mm", c.gapMm},
                  {"relative_density_percent", c.relativeDensityPercent},
                  {"ppi", c.ppi},
                  {"material", c.rear.material},
                  {"core_material", c.coreMaterial}};
        if (c.panelArealDensityGCm2) {
            shield["panel_areal_density_g_cm2"] = *c.panelArealDensityGCm2;
        }
        break;
    case Shield::Honeycomb:
        shield = {{"type", "honeycomb_sandwich"},
                  {"front_facesheet_mm", c.front.thicknessMm},
                  {"rear_facesheet_mm", c.rear.thicknessMm},
                  {"core_thickness_mm", c.gapMm},
                  {"cell_size_mm", c.cellSizeMm},
                  {"facesheet_material", c.rear.material}};
        break;
    }
    return {{"id", c.id},
            {"description", describe(c)},
            {"mode", "performance"},
            {"threat",
             {{"diameter_mm", c.diameterMm},
              {"velocity_km_s", c.velocityKmS},
              {"material", c.projectileMaterial},
              {"density_g_cm3", c.projectileDensityGCm3}}},
            {"shield", shield}};
}

} // namespace hvi::validation
