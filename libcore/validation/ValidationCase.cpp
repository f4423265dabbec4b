#include "validation/ValidationCase.hpp"

#include "io/Resources.hpp"

#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace hvi::validation {

using nlohmann::json;

const char* toString(Shield shield) {
    switch (shield) {
    case Shield::Whipple:
        return "whipple";
    case Shield::Foam:
        return "foam";
    case Shield::Honeycomb:
        return "honeycomb";
    }
    return "whipple";
}

namespace {

/// The source study's material, stated in thesis_cases.json's notes.
constexpr const char* kStudyMaterial = "Al6061-T6";

/// Names the database uses that the tables hold under another name, with why.
std::string mapMaterial(const std::string& name, Case& c) {
    static const std::map<std::string, std::pair<std::string, std::string>> aliases = {
        {"Aluminum", {"Al6061-T6", "unspecified aluminium taken as Al6061-T6"}},
        {"Al5052", {"Al5052-H39", "5052 foil of unstated temper taken as Al5052-H39"}},
    };
    const auto it = aliases.find(name);
    if (it == aliases.end()) {
        return name;
    }
    c.assumptions.push_back(name + ": " + it->second.second);
    return it->second.first;
}

json parse(const char* resource) {
    return json::parse(resources::get(resource));
}

/// The parts every case of the source study shares: all of Al6061-T6 but where stated.
Case studyCase(const json& entry, Shield shield, const json& doc) {
    Case c;
    c.id = entry.at("id");
    c.set = "source_study";
    c.shield = shield;
    c.projectileMaterial = entry.value("projectile_material", kStudyMaterial);
    c.projectileDensityGCm3 = entry.value("projectile_density_g_cm3", 2.70);
    c.diameterMm = entry.at("projectile_diameter_mm");
    c.velocityKmS = entry.at("velocity_km_s");
    c.result = entry.at("expected").at("pnp");
    c.source = doc.at("source");
    c.coreMaterial = shield == Shield::Whipple ? "" : kStudyMaterial;
    return c;
}

void addStudyCases(std::vector<Case>& cases) {
    const json doc = parse("data/validation/thesis_cases.json");
    for (const auto& w : doc.at("whipple")) {
        Case c = studyCase(w, Shield::Whipple, doc);
        c.front = {kStudyMaterial, w.at("bumper_mm")};
        c.rear = {kStudyMaterial, w.at("rear_wall_mm")};
        if (w.at("standoff_mm").is_null()) {
            // The source gives none; the bumper-hole measurement does not depend on it. 100 mm
            // is the nearest standoff at which the JSC equation also calls the wall safe.
            c.gapMm = 100.0;
            c.assumptions.push_back("standoff not given in the source: 100 mm assumed (the JSC "
                                    "equation gives NP with an 18 % margin there)");
        } else {
            c.gapMm = w.at("standoff_mm");
        }
        cases.push_back(c);
    }
    for (const auto& f : doc.at("foam")) {
        Case c = studyCase(f, Shield::Foam, doc);
        c.front = {kStudyMaterial, f.at("facesheet_mm")};
        c.rear = c.front;
        c.gapMm = f.at("standoff_mm");
        c.relativeDensityPercent = f.at("relative_density_percent");
        c.ppi = f.at("ppi");
        if (f.contains("panel_areal_density_g_cm2")) {
            c.panelArealDensityGCm2 = f.at("panel_areal_density_g_cm2").get<double>();
        }
        cases.push_back(c);
    }
    for (const auto& h : doc.at("honeycomb")) {
        Case c = studyCase(h, Shield::Honeycomb, doc);
        c.front = {kStudyMaterial, h.at("facesheet_mm")};
        c.rear = c.front;
        c.gapMm = h.at("core_thickness_mm");
        // The source gives neither (workflows/examples/honeycomb_HITF04150.json says why).
        c.cellSizeMm = h.at("cell_size_mm").is_null() ? 4.7625 : h.at("cell_size_mm").get<double>();
        c.foilThicknessMm =
            h.at("foil_thickness_mm").is_null() ? 0.0254 : h.at("foil_thickness_mm").get<double>();
        c.assumptions.push_back("cell size and foil not given in the source: 3/16 in (4.7625 mm) "
                                "cells of 0.001 in (0.0254 mm) Al6061-T6 foil assumed");
        cases.push_back(c);
    }
}

void addDevelopmentCases(std::vector<Case>& cases) {
    const json doc = parse("data/validation/nasa_tests.json");
    auto common = [](const json& t, Case& c) {
        c.set = "development";
        const json& p = t.at("projectile");
        c.projectileMaterial = mapMaterial(p.at("material"), c);
        c.projectileDensityGCm3 = p.at("density_g_cm3");
        c.diameterMm = p.at("diameter_mm");
        c.velocityKmS = t.at("velocity_km_s");
        c.result = t.at("result");
        c.source = t.at("source");
    };
    for (const auto& t : doc.at("whipple")) {
        Case c;
        c.id = t.at("id");
        c.shield = Shield::Whipple;
        common(t, c);
        c.front = {mapMaterial(t.at("bumper").at("material"), c),
                   t.at("bumper").at("thickness_mm")};
        c.rear = {mapMaterial(t.at("rear_wall").at("material"), c),
                  t.at("rear_wall").at("thickness_mm")};
        if (t.at("rear_wall").contains("yield_ksi")) {
            c.rearYieldKsi = t.at("rear_wall").at("yield_ksi").get<double>();
        }
        c.gapMm = t.at("standoff_mm");
        cases.push_back(c);
    }
    // A sandwich panel's facesheets and core thickness and material.
    auto sandwich = [&](const json& t, const std::string& prefix, Shield shield) {
        Case c;
        c.id = prefix + t.at("id").get<std::string>();
        c.shield = shield;
        common(t, c);
        const json& core = t.at("core");
        c.front = {mapMaterial(t.at("front_facesheet").at("material"), c),
                   t.at("front_facesheet").at("thickness_mm")};
        c.rear = {mapMaterial(t.at("rear_facesheet").at("material"), c),
                  t.at("rear_facesheet").at("thickness_mm")};
        c.gapMm = core.at("thickness_mm");
        c.coreMaterial = mapMaterial(core.at("material"), c);
        return c;
    };
    for (const auto& t : doc.at("foam")) {
        Case c = sandwich(t, "foam-", Shield::Foam);
        const json& core = t.at("core");
        c.relativeDensityPercent = core.at("relative_density_percent");
        c.ppi = core.at("ppi");
        if (t.contains("panel_areal_density_g_cm2")) {
            c.panelArealDensityGCm2 = t.at("panel_areal_density_g_cm2").get<double>();
        }
        cases.push_back(c);
    }
    for (const auto& t : doc.at("honeycomb")) {
        Case c = sandwich(t, "hc-", Shield::Honeycomb);
        const json& core = t.at("core");
        c.cellSizeMm = core.at("cell_size_mm");
        c.foilThicknessMm = core.at("foil_thickness_mm");
        c.assumptions.push_back("cell_size_mm is the database's cell diameter, read as the size "
                                "across flats");
        cases.push_back(c);
    }
}

} // namespace

const std::vector<Case>& allCases() {
    static const std::vector<Case> cases = [] {
        std::vector<Case> all;
        addStudyCases(all);
        addDevelopmentCases(all);
        return all;
    }();
    return cases;
}

std::vector<Case> selectCases(const std::string& selection) {
    std::vector<Case> out;
    if (selection == "quick" || selection == "ci") {
        const std::vector<const char*> ids =
            selection == "ci"
                ? std::vector<const char*>{"HITF03147-2", "A1076"}
                : std::vector<const char*>{"HITF03147-2", "HITF03147-3", "A1076", "A1077"};
        for (const char* id : ids) {
            out.push_back(findCase(id));
        }
        return out;
    }
    if (selection != "all" && selection != "source_study" && selection != "development") {
        throw std::invalid_argument("unknown case selection '" + selection + "'");
    }
    for (const auto& c : allCases()) {
        if (selection == "all" || c.set == selection) {
            out.push_back(c);
        }
    }
    return out;
}

std::vector<Case> interleavedByShield(const std::vector<Case>& cases) {
    const Shield order[] = {Shield::Whipple, Shield::Foam, Shield::Honeycomb};
    std::vector<std::vector<const Case*>> queues(std::size(order));
    for (const auto& c : cases) {
        for (std::size_t k = 0; k < std::size(order); ++k) {
            if (c.shield == order[k]) {
                queues[k].push_back(&c);
            }
        }
    }
    std::vector<Case> out;
    for (std::size_t i = 0; out.size() < cases.size(); ++i) {
        for (const auto& q : queues) {
            if (i < q.size()) {
                out.push_back(*q[i]);
            }
        }
    }
    return out;
}

const Case& findCase(const std::string& id) {
    for (const auto& c : allCases()) {
        if (c.id == id) {
            return c;
        }
    }
    throw std::invalid_argument("no validation case '" + id + "'");
}

} // namespace hvi::validation
