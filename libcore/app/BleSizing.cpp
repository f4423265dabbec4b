#include "app/BleSizing.hpp"

#include "ble/BleMaterials.hpp"
#include "core/Error.hpp"
#include "core/Units.hpp"
#include "io/JsonInput.hpp"

#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>

namespace hvi::app {

using nlohmann::json;
namespace u = units;

namespace {

/// Collects semantic problems so they are all reported together.
struct Problems {
    std::string file;
    std::vector<InputIssue> issues;
    void add(const std::string& pointer, const std::string& problem, const std::string& expected) {
        issues.push_back({file, pointer, problem, expected});
    }
    void throwIfAny() {
        if (!issues.empty()) {
            throw InputError(issues);
        }
    }
};

const ble::BleMaterial* material(const json& block, const char* key, const std::string& ptr,
                                 Problems& problems) {
    const std::string name = block.value(key, "Al6061-T6");
    const ble::BleMaterial* m = ble::findBleMaterial(name);
    if (!m) {
        std::string known;
        for (const auto& n : ble::bleMaterialNames()) {
            known += (known.empty() ? "" : ", ") + n;
        }
        problems.add(ptr + "/" + key, "unknown material '" + name + "'", "one of: " + known);
    }
    return m;
}

/// Rear-wall yield in ksi: an explicit override (ksi or MPa, not both) or the material's.
double rearWallYieldKsi(const json& shield, const ble::BleMaterial* m, const std::string& matKey,
                        Problems& problems) {
    const bool ksi = shield.contains("rear_wall_yield_ksi");
    const bool mpa = shield.contains("rear_wall_yield_MPa");
    if (ksi && mpa) {
        problems.add("/shield/rear_wall_yield_MPa", "both rear_wall_yield_ksi and _MPa given",
                     "one of them");
        return 40.0;
    }
    if (ksi) {
        return shield.at("rear_wall_yield_ksi");
    }
    if (mpa) {
        return u::mpaToKsi(shield.at("rear_wall_yield_MPa").get<double>());
    }
    if (m && !m->yieldKsi) {
        problems.add("/shield/" + matKey, "material '" + m->name + "' has no yield stress",
                     "a structural alloy, or rear_wall_yield_ksi / _MPa");
        return 40.0;
    }
    return m ? *m->yieldKsi : 40.0;
}

/// (front, rear) facesheet thickness [mm] from facesheet_mm or front_/rear_facesheet_mm.
std::pair<double, double> facesheets(const json& shield, Problems& problems) {
    const bool both = shield.contains("facesheet_mm");
    const bool front = shield.contains("front_facesheet_mm");
    const bool rear = shield.contains("rear_facesheet_mm");
    if (both && (front || rear)) {
        problems.add("/shield/facesheet_mm", "facesheet_mm given together with front_/rear_",
                     "either facesheet_mm or both front_facesheet_mm and rear_facesheet_mm");
        return {1.0, 1.0};
    }
    if (both) {
        const double t = shield.at("facesheet_mm");
        return {t, t};
    }
    if (!front || !rear) {
        problems.add(front ? "/shield/rear_facesheet_mm" : "/shield/front_facesheet_mm",
                     "required key is missing",
                     "facesheet thickness [mm] (or facesheet_mm for both)");
        return {1.0, 1.0};
    }
    return {shield.at("front_facesheet_mm"), shield.at("rear_facesheet_mm")};
}

double requireMm(const json& shield, const char* key, const std::string& mode, Problems& problems) {
    if (!shield.contains(key)) {
        problems.add(std::string("/shield/") + key, "required key is missing in " + mode + " mode",
                     "thickness [mm], > 0");
        return 1.0;
    }
    return shield.at(key);
}

std::string verdictOf(double diameterCm, double criticalCm) {
    return diameterCm > criticalCm ? "P" : "NP";
}

json warningsJson(const std::vector<ble::ValidityWarning>& warnings) {
    json out = json::array();
    for (const auto& w : warnings) {
        out.push_back({{"code", w.code}, {"message", w.message}});
    }
    return out;
}

json performanceJson(const std::string& equation, const ble::CriticalDiameterResult& r,
                     double diameterCm) {
    return {{"equation", equation},
            {"critical_diameter_mm", u::cmToMm(r.criticalDiameterCm)},
            {"regime", ble::regimeName(r.regime)},
            {"verdict", verdictOf(diameterCm, r.criticalDiameterCm)},
            {"critical_over_projectile_diameter", r.criticalDiameterCm / diameterCm}};
}

void addWarnings(std::vector<ble::ValidityWarning>& into,
                 const std::vector<ble::ValidityWarning>& from) {
    for (const auto& w : from) {
        const bool seen = std::any_of(into.begin(), into.end(), [&](const auto& x) {
            return x.code == w.code && x.message == w.message;
        });
        if (!seen) {
            into.push_back(w);
        }
    }
}

} // namespace

namespace {

/// The foam core's density for the foam BLE [g/cm3]: measured (foam_density_g_cm3, or from
/// the panel's measured areal density), as FOAM10 fitted its constants, or else nominal
/// (relative density x the ligament alloy's density) with a warning: nominal densities of the
/// tested "6-8 %" cores are 10-35 % below their measured 0.21-0.25 g/cm3 (FOAM10 Table 1).
double foamDensityGCm3(const json& shield, double facesheetDensity, double facesheetsCm,
                       double coreMm, Problems& problems,
                       std::vector<ble::ValidityWarning>& warnings) {
    if (shield.contains("foam_density_g_cm3")) {
        return shield.at("foam_density_g_cm3").get<double>();
    }
    if (shield.contains("panel_areal_density_g_cm2")) {
        const double panelAd = shield.at("panel_areal_density_g_cm2").get<double>();
        const double coreAd = panelAd - facesheetDensity * facesheetsCm;
        if (!(coreAd > 0.0)) {
            problems.add("/shield/panel_areal_density_g_cm2",
                         "is not more than the facesheets' own areal density",
                         "the whole panel's measured areal density [g/cm2]");
            problems.throwIfAny();
        }
        return coreAd / u::mmToCm(coreMm);
    }
    const std::string coreMaterial =
        shield.value("core_material", shield.value("material", std::string("Al6061-T6")));
    const ble::BleMaterial* m = ble::findBleMaterial(coreMaterial);
    if (!m) {
        problems.add("/shield/core_material", "unknown material '" + coreMaterial + "'",
                     "a name from ble-size --list-materials");
        problems.throwIfAny();
    }
    warnings.push_back({"foam_density_nominal",
                        "foam density from the nominal relative density x " + coreMaterial +
                            ": FOAM10 fitted its constants with measured core densities, "
                            "10-35 % higher for the tested 6-8 % cores; give "
                            "panel_areal_density_g_cm2 or foam_density_g_cm3"});
    return m->densityGCm3 * shield.at("relative_density_percent").get<double>() / 100.0;
}

/// A result beyond the range of a double (a 1e308 mm core gives d_c = inf) is a failed
/// computation (exit 3), not bad input: every input is a legal number the equations take,
/// and which of them drove the result out of range depends on the equation, so no single
/// pointer could be named. Written out, inf became null in the file and was judged NP.
void requireFiniteResults(const BleSizingOutcome& out) {
    const std::string advice = ": the equation's result is beyond the range of a double; the "
                               "inputs are far outside what it describes (no output written)";
    try {
        io::requireFiniteNumbers(out.sizing, "<sizing>");
    } catch (const InputError& e) {
        const std::string& pointer = e.issues().front().pointer;
        const double value = out.sizing.at(json::json_pointer(pointer)).get<double>();
        const std::string shown = std::isnan(value) ? "NaN" : (value > 0.0 ? "inf" : "-inf");
        throw RuntimeFailure(pointer + " is " + shown + advice);
    }
    for (const auto& point : out.curve.points) {
        if (!std::isfinite(point.criticalDiameterCm)) {
            throw RuntimeFailure("the ballistic limit curve at " +
                                 std::to_string(point.velocityKmS) + " km/s" + advice);
        }
    }
}

} // namespace

namespace {

using CurveOf = std::function<ble::CriticalDiameterResult(double)>;

/// What every shield type's sizing reads, and where it writes.
struct SizingContext {
    const json& shield;
    const json& options;
    std::string mode;
    bool design = false;
    ble::Threat threat;
    bool thesisCompat = false;
    ble::YieldRatioConvention convention = ble::YieldRatioConvention::Handbook;
    ble::NnoShatterConstants constants = ble::NnoShatterConstants::Printed;
    double standoffMinMm = 0.0, standoffMaxMm = 0.0;
    Problems& problems;
    json& sizing;
    BleSizingOutcome& out;
};

/// The curve's value at the threat's velocity: its warnings, the performance block and the
/// curve's label; returns the curve.
CurveOf recordPerformance(SizingContext& c, CurveOf curveOf, const std::string& equation,
                          const std::string& label) {
    const auto r = curveOf(c.threat.velocityKmS);
    addWarnings(c.out.warnings, r.warnings);
    c.sizing["performance"] = performanceJson(equation, r, c.threat.diameterCm);
    c.out.curveLabel = label;
    return curveOf;
}

/// A threat at velocity v, the rest as given.
ble::Threat atVelocity(const ble::Threat& threat, double v) {
    ble::Threat t = threat;
    t.velocityKmS = v;
    return t;
}

/// What both Whipple equations read of the shield: the rear wall's yield [ksi], the
/// standoff [cm] and the plates' densities [g/cm^3] (2.7 for an unknown material, which is
/// reported with the other problems).
struct WhippleFrame {
    double yield, standoffCm, rhoB, rhoW;
};

WhippleFrame whippleFrame(SizingContext& c, const ble::BleMaterial* bumper,
                          const ble::BleMaterial* wall) {
    return {rearWallYieldKsi(c.shield, wall, "rear_wall_material", c.problems),
            u::mmToCm(c.shield.at("standoff_mm").get<double>()), bumper ? bumper->densityGCm3 : 2.7,
            wall ? wall->densityGCm3 : 2.7};
}

CurveOf sizeWhipple(SizingContext& c, const WhippleFrame& f) {
    const json& shield = c.shield;
    const double yield = f.yield, standoffCm = f.standoffCm, rhoB = f.rhoB;
    ble::WhippleShield w{0.0, rhoB, 0.0, yield, standoffCm};
    if (c.design) {
        c.problems.throwIfAny();
        const auto d = ble::designWhipple(c.threat, {rhoB, yield, standoffCm}, c.convention);
        addWarnings(c.out.warnings, d.warnings);
        w.bumperCm = d.bumperCm;
        w.rearWallCm = d.rearWallCm;
        c.sizing["design"] = {
            {"equation", "HB09 4-21, 4-22 (Whipple design)"},
            {"bumper_mm", u::cmToMm(d.bumperCm)},
            {"rear_wall_mm", u::cmToMm(d.rearWallCm)},
            {"bumper_coefficient", d.bumperCoefficient},
            {"yield_ratio_convention", c.thesisCompat ? "thesis_inverted" : "handbook"}};
    } else {
        w.bumperCm = u::mmToCm(requireMm(shield, "bumper_mm", c.mode, c.problems));
        w.rearWallCm = u::mmToCm(requireMm(shield, "rear_wall_mm", c.mode, c.problems));
    }
    c.problems.throwIfAny();
    const ble::Threat threat = c.threat;
    const auto constants = c.constants;
    CurveOf curveOf = recordPerformance(
        c,
        [=](double v) {
            return ble::whippleNnoCriticalDiameter(w, atVelocity(threat, v), constants);
        },
        "NASA JSC new non-optimum Whipple (C93 eqs 9-12)", "Whipple NNO");
    // What foam2layers needs next (its panel type whipple).
    c.sizing["panel"] = {{"type", "whipple"},
                         {"front_facesheet_mm", u::cmToMm(w.bumperCm)},
                         {"core_thickness_mm", shield.at("standoff_mm")},
                         {"rear_facesheet_mm", u::cmToMm(w.rearWallCm)},
                         {"front_facesheet_material", shield.at("bumper_material")},
                         {"rear_facesheet_material", shield.at("rear_wall_material")}};
    return curveOf;
}

CurveOf sizeStuffedWhipple(SizingContext& c, const WhippleFrame& f) {
    const json& shield = c.shield;
    const double yield = f.yield, standoffCm = f.standoffCm, rhoB = f.rhoB, rhoW = f.rhoW;
    ble::StuffedWhippleShield sw;
    sw.bumperDensityGCm3 = rhoB;
    sw.rearWallDensityGCm3 = rhoW;
    sw.rearWallYieldKsi = yield;
    sw.standoffCm = standoffCm;
    if (c.design) {
        c.problems.throwIfAny();
        const auto d = ble::designStuffedWhipple(c.threat, {rhoB, rhoW, yield, standoffCm});
        addWarnings(c.out.warnings, d.warnings);
        sw.bumperCm = d.bumperCm;
        sw.stuffingArealDensityGCm2 = d.stuffingArealDensityGCm2;
        sw.rearWallCm = d.rearWallCm;
        c.sizing["design"] = {{"equation", "HB09 4-45..4-47 (stuffed Whipple design)"},
                              {"bumper_mm", u::cmToMm(d.bumperCm)},
                              {"blanket_areal_density_g_cm2", d.stuffingArealDensityGCm2},
                              {"nextel_areal_density_g_cm2", d.nextelArealDensityGCm2},
                              {"kevlar_areal_density_g_cm2", d.kevlarArealDensityGCm2},
                              {"rear_wall_mm", u::cmToMm(d.rearWallCm)}};
    } else {
        sw.bumperCm = u::mmToCm(requireMm(shield, "bumper_mm", c.mode, c.problems));
        sw.rearWallCm = u::mmToCm(requireMm(shield, "rear_wall_mm", c.mode, c.problems));
        if (!shield.contains("blanket_areal_density_g_cm2")) {
            c.problems.add("/shield/blanket_areal_density_g_cm2",
                           "required key is missing in performance mode",
                           "Nextel + Kevlar areal density [g/cm^2], > 0");
        } else {
            sw.stuffingArealDensityGCm2 = shield.at("blanket_areal_density_g_cm2");
        }
    }
    c.problems.throwIfAny();
    const ble::Threat threat = c.threat;
    return recordPerformance(
        c, [=](double v) { return ble::stuffedWhippleCriticalDiameter(sw, atVelocity(threat, v)); },
        "stuffed Whipple (HB09 4-48..4-50)", "stuffed Whipple");
}

CurveOf sizeSingleWall(SizingContext& c) {
    const json& shield = c.shield;
    const ble::BleMaterial* m = material(shield, "material", "/shield", c.problems);
    if (m && (!m->brinellHardness || !m->soundSpeedKmS)) {
        c.problems.add("/shield/material",
                       "material '" + m->name + "' has no Brinell hardness or sound speed",
                       "an aluminium alloy of the BLE table");
    }
    const std::string fm = shield.at("failure_mode");
    const auto failure = fm == "perforation"      ? ble::SingleWallFailure::Perforation
                         : fm == "detached_spall" ? ble::SingleWallFailure::DetachedSpall
                                                  : ble::SingleWallFailure::IncipientSpall;
    c.problems.throwIfAny();
    ble::SingleWallTarget target{0.0, m->densityGCm3, *m->brinellHardness, *m->soundSpeedKmS};
    if (c.design) {
        target.thicknessCm = ble::singleWallRequiredThicknessCm(c.threat, target, failure);
        c.sizing["design"] = {{"equation", "Cour-Palais (HB09 4-1..4-5)"},
                              {"thickness_mm", u::cmToMm(target.thicknessCm)},
                              {"semi_infinite_penetration_mm",
                               u::cmToMm(ble::semiInfinitePenetrationCm(c.threat, target))}};
    } else {
        target.thicknessCm = u::mmToCm(requireMm(shield, "thickness_mm", c.mode, c.problems));
        c.problems.throwIfAny();
    }
    const ble::Threat threat = c.threat;
    CurveOf curveOf = recordPerformance(
        c,
        [=](double v) {
            return ble::singleWallCriticalDiameter(target, atVelocity(threat, v), failure);
        },
        "Cour-Palais single wall (HB09 4-6), " + fm, "single wall (" + fm + ")");
    c.sizing["panel"] = {{"type", "single_wall"},
                         {"rear_facesheet_mm", u::cmToMm(target.thicknessCm)},
                         {"rear_facesheet_material", shield.at("material")}};
    return curveOf;
}

CurveOf sizeHoneycomb(SizingContext& c) {
    const json& shield = c.shield;
    const ble::BleMaterial* m = material(shield, "facesheet_material", "/shield", c.problems);
    const double yield = rearWallYieldKsi(shield, m, "facesheet_material", c.problems);
    const std::string equation = shield.at("equation");
    if (equation == "handbook" && !shield.contains("cell_size_mm")) {
        c.problems.add("/shield/cell_size_mm", "required key is missing for equation 'handbook'",
                       "honeycomb cell size across flats [mm], > 0");
    }
    ble::HoneycombSandwichPanel panel;
    panel.frontFacesheetDensityGCm3 = m ? m->densityGCm3 : 2.7;
    panel.rearFacesheetYieldKsi = yield;
    panel.coreThicknessCm = u::mmToCm(shield.at("core_thickness_mm").get<double>());
    panel.cellSizeCm = u::mmToCm(shield.value("cell_size_mm", 0.0));
    if (c.design) {
        c.problems.throwIfAny();
        const double t = ble::srlFacesheetDesignCm(c.threat, panel.frontFacesheetDensityGCm3, yield,
                                                   panel.coreThicknessCm);
        panel.frontFacesheetCm = panel.rearFacesheetCm = t;
        c.sizing["design"] = {{"equation", "SRL facesheet sizing (BLAP09 eq 57, t_b = t_w)"},
                              {"facesheet_mm", u::cmToMm(t)}};
    } else {
        const auto [front, rear] = facesheets(shield, c.problems);
        panel.frontFacesheetCm = u::mmToCm(front);
        panel.rearFacesheetCm = u::mmToCm(rear);
    }
    c.problems.throwIfAny();
    const ble::Threat threat = c.threat;
    const bool srl = equation == "srl";
    CurveOf curveOf = recordPerformance(
        c,
        [=](double v) {
            const ble::Threat t = atVelocity(threat, v);
            return srl ? ble::srlCriticalDiameter(panel, t)
                       : ble::honeycombHandbookCriticalDiameter(panel, t);
        },
        srl ? "Schaefer-Ryan-Lambert honeycomb sandwich (BLAP09 eqs 56-60)"
            : "HB09 6-1: Whipple NNO with S = min(2 D_cell, t_core)",
        srl ? "honeycomb (SRL)" : "honeycomb (HB09 6-1)");
    // What hcomb2rings needs next; the cell and foil pass through (the equations use the cell
    // size at most), and hcomb2rings names what is still missing.
    json next = {{"type", "honeycomb_sandwich"},
                 {"front_facesheet_mm", u::cmToMm(panel.frontFacesheetCm)},
                 {"rear_facesheet_mm", u::cmToMm(panel.rearFacesheetCm)},
                 {"core_thickness_mm", shield.at("core_thickness_mm")},
                 {"facesheet_material", shield.at("facesheet_material")}};
    for (const char* key : {"cell_size_mm", "foil_thickness_mm", "foil_material"}) {
        if (shield.contains(key)) {
            next[key] = shield.at(key);
        }
    }
    c.sizing["panel"] = next;
    return curveOf;
}

const char* initialStandoffStatusName(ble::InitialStandoffStatus status) {
    return status == ble::InitialStandoffStatus::Solved                 ? "solved"
           : status == ble::InitialStandoffStatus::NoSolutionInEnvelope ? "no_solution"
                                                                        : "at_envelope_minimum";
}

/// The source study's step 2 for a foam panel: the initial standoff of the even-split
/// Whipple of equal areal mass, and the three mass splits at the core thickness (given, or
/// that standoff). Writes sizing["thesis_workflow"]; returns the core thickness [mm].
double thesisWorkflow(SizingContext& c, ble::FoamPanelSpec spec, bool hasCore) {
    const json& shield = c.shield;
    const ble::ThesisSizingOptions thesisOptions{c.convention, c.constants};
    const auto initial = ble::thesisInitialStandoff(spec, c.threat, u::mmToCm(c.standoffMinMm),
                                                    u::mmToCm(c.standoffMaxMm), thesisOptions);
    addWarnings(c.out.warnings, initial.warnings);
    json workflow;
    const char* statusName = initialStandoffStatusName(initial.status);
    workflow["initial_standoff"] = {
        {"equation", "thesis eq 29: even-split Whipple of equal areal mass, d_c(S) = d, "
                     "solved by Brent's method"},
        {"status", statusName},
        {"standoff_mm", u::cmToMm(initial.standoffCm)},
        {"plate_mm", u::cmToMm(initial.plateCm)},
        {"critical_diameter_mm", u::cmToMm(initial.criticalDiameterCm)},
        {"iterations", initial.iterations},
        {"message", initial.message}};
    const bool solved = initial.status == ble::InitialStandoffStatus::Solved;
    const double coreMm =
        hasCore ? shield.at("core_thickness_mm").get<double>() : u::cmToMm(initial.standoffCm);
    spec.coreThicknessCm = u::mmToCm(coreMm);
    const auto splits = ble::thesisMassSplits(spec, c.threat, thesisOptions);
    workflow["splits_at_core_thickness_mm"] = coreMm;
    workflow["equivalent_solid_foam_mm"] = u::cmToMm(splits.solidFoamCm);
    workflow["total_plate_mm"] = u::cmToMm(splits.totalPlateCm);
    workflow["yield_ratio_convention"] = c.thesisCompat ? "thesis_inverted" : "handbook";
    workflow["nno_constants"] = c.options.at("nno_constants");
    json splitList = json::array();
    for (const auto& s : splits.splits) {
        json entry = {{"model", ble::massSplitName(s.model)}, {"feasible", s.feasible}};
        if (s.feasible) {
            entry["bumper_mm"] = u::cmToMm(s.bumperCm);
            entry["rear_wall_mm"] = u::cmToMm(s.rearWallCm);
            entry["critical_diameter_mm"] = u::cmToMm(s.performance.criticalDiameterCm);
            entry["regime"] = ble::regimeName(s.performance.regime);
            entry["verdict"] = s.perforated ? "P" : "NP";
            addWarnings(c.out.warnings, s.designWarnings);
        } else {
            entry["reason"] = s.infeasibleReason;
        }
        splitList.push_back(entry);
    }
    workflow["mass_splits"] = splitList;
    c.sizing["thesis_workflow"] = workflow;
    if (!hasCore && !solved) {
        c.out.warnings.push_back({"initial_standoff_" + std::string(statusName), initial.message});
    }
    return coreMm;
}

CurveOf sizeFoam(SizingContext& c) {
    const json& shield = c.shield;
    const ble::BleMaterial* m = material(shield, "material", "/shield", c.problems);
    const double yield = rearWallYieldKsi(shield, m, "material", c.problems);
    const auto [front, rear] = facesheets(shield, c.problems);
    c.problems.throwIfAny();
    const double rho = m->densityGCm3;
    const double relDensity = shield.at("relative_density_percent");
    const double ppi = shield.at("ppi");
    const bool hasCore = shield.contains("core_thickness_mm");
    if (!hasCore && !c.design) {
        c.problems.add("/shield/core_thickness_mm", "required key is missing in performance mode",
                       "foam core thickness [mm], > 0 (or mode \"design\")");
        c.problems.throwIfAny();
    }
    const double frontCm = u::mmToCm(front), rearCm = u::mmToCm(rear);
    if (hasCore && shield.at("core_thickness_mm").get<double>() <= front + rear) {
        c.problems.add("/shield/core_thickness_mm",
                       "core not thicker than the two facesheets together",
                       "core_thickness_mm > front + rear facesheet [mm]");
        c.problems.throwIfAny();
    }
    ble::FoamPanelSpec spec;
    spec.frontFacesheetCm = frontCm;
    spec.rearFacesheetCm = rearCm;
    spec.relativeDensityPercent = relDensity;
    spec.foamMaterialDensityGCm3 = rho;
    spec.plateDensityGCm3 = rho;
    spec.plateYieldKsi = yield;
    const double coreMm = thesisWorkflow(c, spec, hasCore);

    // The direct foam-panel BLE (Ryan et al. 2010) where the core is known.
    ble::FoamSandwichPanel panel;
    panel.frontFacesheetCm = frontCm;
    panel.frontFacesheetDensityGCm3 = rho;
    panel.rearFacesheetCm = rearCm;
    panel.rearFacesheetDensityGCm3 = rho;
    panel.rearFacesheetYieldKsi = yield;
    panel.coreThicknessCm = u::mmToCm(coreMm);
    panel.foamDensityGCm3 =
        foamDensityGCm3(shield, rho, frontCm + rearCm, coreMm, c.problems, c.out.warnings);
    panel.poresPerInch = ppi;
    const ble::Threat threat = c.threat;
    CurveOf curveOf = recordPerformance(
        c,
        [=](double v) { return ble::foamSandwichCriticalDiameter(panel, atVelocity(threat, v)); },
        "Ryan et al. 2010 open-cell foam sandwich (FOAM10 eqs 1-5)", "foam sandwich (Ryan 2010)");

    // What foam2layers needs next.
    c.sizing["panel"] = {{"type", "foam_sandwich"},
                         {"front_facesheet_mm", front},
                         {"rear_facesheet_mm", rear},
                         {"core_thickness_mm", coreMm},
                         {"core_thickness_source", hasCore ? "given" : "initial_standoff"},
                         {"relative_density_percent", relDensity},
                         {"ppi", ppi},
                         {"material", shield.at("material")}};
    if (shield.contains("core_material")) {
        c.sizing["panel"]["core_material"] = shield.at("core_material");
    }
    return curveOf;
}

/// The threat block's numbers; unknown materials and bad curve/standoff ranges are collected.
ble::Threat readThreat(const json& threatIn, Problems& problems) {
    const ble::BleMaterial* projectile = material(threatIn, "material", "/threat", problems);
    ble::Threat threat;
    threat.diameterCm = u::mmToCm(threatIn.at("diameter_mm").get<double>());
    threat.velocityKmS = threatIn.at("velocity_km_s");
    threat.angleDeg = threatIn.at("angle_deg");
    threat.densityGCm3 = threatIn.contains("density_g_cm3")
                             ? threatIn.at("density_g_cm3").get<double>()
                             : (projectile ? projectile->densityGCm3 : 2.7);
    return threat;
}

void checkRanges(const json& options, Problems& problems) {
    if (options.at("curve_velocity_max_km_s").get<double>() <=
        options.at("curve_velocity_min_km_s").get<double>()) {
        problems.add("/options/curve_velocity_max_km_s", "not above curve_velocity_min_km_s",
                     "curve_velocity_max_km_s > curve_velocity_min_km_s");
    }
    if (options.at("standoff_max_mm").get<double>() <=
        options.at("standoff_min_mm").get<double>()) {
        problems.add("/options/standoff_max_mm", "not above standoff_min_mm",
                     "standoff_max_mm > standoff_min_mm");
    }
}

} // namespace

BleSizingOutcome computeSizing(const json& doc, const std::string& file) {
    Problems problems{file, {}};
    BleSizingOutcome out;
    json sizing;
    const json& threatIn = doc.at("threat");
    const json& options = doc.at("options");
    SizingContext c{
        doc.at("shield"), options, doc.at("mode"), false, {}, false, {}, {}, 0.0, 0.0, problems,
        sizing,           out};
    c.design = c.mode == "design";
    c.threat = readThreat(threatIn, problems);
    checkRanges(options, problems);
    c.standoffMinMm = options.at("standoff_min_mm");
    c.standoffMaxMm = options.at("standoff_max_mm");
    c.thesisCompat = options.at("thesis_compat");
    c.convention = c.thesisCompat ? ble::YieldRatioConvention::ThesisInverted
                                  : ble::YieldRatioConvention::Handbook;
    c.constants = options.at("nno_constants") == "continuous" ? ble::NnoShatterConstants::Continuous
                                                              : ble::NnoShatterConstants::Printed;
    sizing["id"] = doc.at("id");
    if (doc.contains("description")) {
        sizing["description"] = doc.at("description");
    }
    sizing["mode"] = c.mode;

    const std::string type = c.shield.at("type");
    CurveOf curveOf;
    if (type == "whipple" || type == "stuffed_whipple") {
        const ble::BleMaterial* bumper = material(c.shield, "bumper_material", "/shield", problems);
        const ble::BleMaterial* wall =
            material(c.shield, "rear_wall_material", "/shield", problems);
        const WhippleFrame frame = whippleFrame(c, bumper, wall);
        curveOf = type == "whipple" ? sizeWhipple(c, frame) : sizeStuffedWhipple(c, frame);
    } else if (type == "single_wall") {
        curveOf = sizeSingleWall(c);
    } else if (type == "honeycomb_sandwich") {
        curveOf = sizeHoneycomb(c);
    } else { // foam_sandwich
        curveOf = sizeFoam(c);
    }

    const ble::Threat& threat = c.threat;
    sizing["threat"] = {
        {"diameter_mm", threatIn.at("diameter_mm")},
        {"velocity_km_s", threat.velocityKmS},
        {"angle_deg", threat.angleDeg},
        {"normal_velocity_km_s", threat.velocityKmS * std::cos(u::degToRad(threat.angleDeg))},
        {"material", threatIn.at("material")},
        {"density_g_cm3", threat.densityGCm3}};
    sizing["shield"] = c.shield;
    if (curveOf) {
        out.curve = ble::sampleBallisticLimitCurve(curveOf, options.at("curve_velocity_min_km_s"),
                                                   options.at("curve_velocity_max_km_s"),
                                                   options.at("curve_points").get<std::size_t>());
        out.hasCurve = true;
    }
    sizing["warnings"] = warningsJson(out.warnings);
    out.sizing = sizing;
    requireFiniteResults(out);
    return out;
}

} // namespace hvi::app
