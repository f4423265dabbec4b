#include "app/BleSizeTool.hpp"

#include "app/BleSizing.hpp"
#include "ble/BleMaterials.hpp"
#include "core/Units.hpp"
#include "io/AtomicOutput.hpp"
#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"
#include "plot/XyPlot.hpp"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace hvi::app {

using nlohmann::json;

BleSizeTool::BleSizeTool()
    : tool::Tool("ble-size", "Ballistic-limit sizing of MMOD shields (NASA JSC equations, the "
                             "source study's foam-to-Whipple method, ballistic limit curves)") {}

void BleSizeTool::addOptions(CLI::App& app) {
    app.add_option("constraints", m_input,
                   "Constraints JSON (threat and shield; '-' for stdin). Flags override it; "
                   "without it the flags describe the case")
        ->check(CLI::ExistingFile | CLI::IsMember({"-"}));
    app.add_option("-o,--output", m_output, "Sizing JSON to write ('-' = stdout)");
    app.add_option("--curve", m_curveCsv, "Also write the ballistic limit curve d_c(V) as CSV");
    app.add_option("--plot", m_plot, "Also draw the ballistic limit curve (.svg or .png)");
    app.add_option("--overlay", m_overlay,
                   "Test points to draw on the plot: JSON with arrays of shots holding "
                   "velocity_km_s, projectile_diameter_mm and expected.pnp (the format of the "
                   "source study's validation file)")
        ->check(CLI::ExistingFile);
    app.add_option("--mode", m_mode,
                   "performance (d_c of the given shield) or design "
                   "(thicknesses for the threat)")
        ->check(CLI::IsMember({"performance", "design"}));
    app.add_option("--type", m_type, "Shield type")
        ->check(CLI::IsMember(
            {"whipple", "single_wall", "honeycomb_sandwich", "foam_sandwich", "stuffed_whipple"}));
    app.add_flag("--thesis-compat", m_thesisCompat,
                 "Reproduce the source study's Table V: rear-wall design equation with the "
                 "yield ratio inverted, (sigma/70)^0.5. Off = the handbook form (70/sigma)^0.5");
    app.add_option("--nno-constants", m_nnoConstants,
                   "Whipple shatter-regime constants: printed (C93/HB09, default) or continuous")
        ->check(CLI::IsMember({"printed", "continuous"}));
    app.add_flag("--list-materials", m_listMaterials, "List the BLE material table and exit");

    struct NumberFlag {
        const char* flag;
        const char* pointer;
        const char* help;
    };
    static const NumberFlag flags[] = {
        {"--diameter-mm", "/threat/diameter_mm", "Projectile diameter [mm]"},
        {"--velocity-km-s", "/threat/velocity_km_s", "Impact speed [km/s]"},
        {"--angle-deg", "/threat/angle_deg", "Impact angle from the normal [deg], 0..90"},
        {"--projectile-density-g-cm3", "/threat/density_g_cm3", "Projectile density [g/cm^3]"},
        {"--bumper-mm", "/shield/bumper_mm", "Bumper thickness [mm]"},
        {"--rear-wall-mm", "/shield/rear_wall_mm", "Rear-wall thickness [mm]"},
        {"--standoff-mm", "/shield/standoff_mm", "Bumper-to-rear-wall gap [mm]"},
        {"--thickness-mm", "/shield/thickness_mm", "Single-wall thickness [mm]"},
        {"--facesheet-mm", "/shield/facesheet_mm", "Both facesheets' thickness [mm]"},
        {"--core-thickness-mm", "/shield/core_thickness_mm", "Sandwich core thickness [mm]"},
        {"--cell-size-mm", "/shield/cell_size_mm", "Honeycomb cell size across flats [mm]"},
        {"--relative-density-percent", "/shield/relative_density_percent",
         "Foam relative density [%]"},
        {"--ppi", "/shield/ppi", "Foam pores per inch [1/in]"},
        {"--blanket-areal-density-g-cm2", "/shield/blanket_areal_density_g_cm2",
         "Stuffed Whipple Nextel+Kevlar areal density [g/cm^2]"},
        {"--yield-ksi", "/shield/rear_wall_yield_ksi", "Rear-wall yield stress [ksi]"},
        {"--yield-MPa", "/shield/rear_wall_yield_MPa", "Rear-wall yield stress [MPa]"},
        {"--curve-velocity-min-km-s", "/options/curve_velocity_min_km_s",
         "Ballistic limit curve: lowest speed [km/s] (default 0.5)"},
        {"--curve-velocity-max-km-s", "/options/curve_velocity_max_km_s",
         "Ballistic limit curve: highest speed [km/s] (default 15)"},
    };
    for (const auto& f : flags) {
        CLI::Option* option =
            app.add_option_function<double>(
                   f.flag, [this, p = std::string(f.pointer)](double v) { m_numbers[p] = v; },
                   f.help)
                ->type_name("NUM");
        flagSetsPointer(option, f.pointer);
    }
    struct StringFlag {
        const char* flag;
        const char* pointer;
        const char* help;
    };
    static const StringFlag stringFlags[] = {
        {"--projectile-material", "/threat/material", "Projectile material name"},
        {"--bumper-material", "/shield/bumper_material", "Whipple bumper material"},
        {"--rear-wall-material", "/shield/rear_wall_material", "Whipple rear-wall material"},
        {"--material", "/shield/material", "Single-wall or foam-panel material"},
        {"--facesheet-material", "/shield/facesheet_material", "Honeycomb facesheet material"},
    };
    for (const auto& f : stringFlags) {
        app.add_option_function<std::string>(
               f.flag,
               [this, p = std::string(f.pointer)](const std::string& v) { m_strings[p] = v; },
               std::string(f.help) + " (--list-materials)")
            ->type_name("NAME");
    }
}

namespace {

void writeCurveCsv(const std::string& path, const BleSizingOutcome& outcome) {
    std::ostringstream csv;
    csv << "# ballistic limit curve: " << outcome.curveLabel << "\n";
    csv << "velocity_km_s,critical_diameter_mm,regime\n";
    char line[128];
    for (const auto& p : outcome.curve.points) {
        std::snprintf(line, sizeof line, "%.6f,%.6f,%s\n", p.velocityKmS,
                      units::cmToMm(p.criticalDiameterCm), ble::regimeName(p.regime));
        csv << line;
    }
    io::writeTextAtomically(path, csv.str());
}

/// Test shots from any arrays of objects with velocity_km_s, projectile_diameter_mm and
/// expected.pnp, anywhere in the document.
void collectShots(const json& node, std::vector<double>& vP, std::vector<double>& dP,
                  std::vector<double>& vNp, std::vector<double>& dNp) {
    if (node.is_array()) {
        for (const auto& item : node) {
            collectShots(item, vP, dP, vNp, dNp);
        }
    } else if (node.is_object()) {
        if (node.contains("velocity_km_s") && node.contains("projectile_diameter_mm") &&
            node.contains("expected") && node["expected"].contains("pnp") &&
            node["velocity_km_s"].is_number() && node["projectile_diameter_mm"].is_number()) {
            const bool perforated = node["expected"]["pnp"].get<std::string>().rfind("P", 0) == 0 &&
                                    node["expected"]["pnp"] != "NP";
            (perforated ? vP : vNp).push_back(node["velocity_km_s"]);
            (perforated ? dP : dNp).push_back(node["projectile_diameter_mm"]);
            return;
        }
        for (const auto& [k, v] : node.items()) {
            collectShots(v, vP, dP, vNp, dNp);
        }
    }
}

} // namespace

void BleSizeTool::execute() {
    if (m_listMaterials) {
        for (const auto& name : ble::bleMaterialNames()) {
            const auto* m = ble::findBleMaterial(name);
            std::cout << name << ": density " << m->densityGCm3 << " g/cm^3";
            if (m->yieldKsi) {
                std::cout << ", yield " << *m->yieldKsi << " ksi";
            }
            if (m->brinellHardness) {
                std::cout << ", BHN " << *m->brinellHardness;
            }
            if (m->soundSpeedKmS) {
                std::cout << ", C " << *m->soundSpeedKmS << " km/s";
            }
            std::cout << " (" << m->source << ")\n";
        }
        return;
    }
    // The document: the file, with flags laid over it.
    json doc = m_input.empty() ? json::object() : io::readJsonFile(m_input);
    const bool flagsUsed = !m_numbers.empty() || !m_strings.empty() || !m_mode.empty() ||
                           !m_type.empty() || m_thesisCompat || !m_nnoConstants.empty();
    const std::string label = m_input.empty() ? std::string("<flags>")
                              : flagsUsed     ? m_input + "+flags"
                                              : m_input;
    if (!doc.is_object()) {
        throw InputError(label, "", "is not a JSON object", "{\"threat\": ..., \"shield\": ...}");
    }
    for (const auto& [pointer, value] : m_numbers) {
        doc[json::json_pointer(pointer)] = value;
    }
    for (const auto& [pointer, value] : m_strings) {
        doc[json::json_pointer(pointer)] = value;
    }
    if (!m_mode.empty()) {
        doc["mode"] = m_mode;
    }
    if (!m_type.empty()) {
        doc["shield"]["type"] = m_type;
    }
    if (m_thesisCompat) {
        doc["options"]["thesis_compat"] = true;
    }
    if (!m_nnoConstants.empty()) {
        doc["options"]["nno_constants"] = m_nnoConstants;
    }
    io::requireFiniteNumbers(doc, label);
    io::validateAgainstSchema(doc, "constraints", label);
    const json resolved = io::withSchemaDefaults(doc, "constraints");

    BleSizingOutcome outcome;
    try {
        outcome = computeSizing(resolved, label);
    } catch (const std::invalid_argument& e) {
        throw InputError(label, "", e.what(), "physical values");
    }
    for (const auto& w : outcome.warnings) {
        warn(w.message + " [" + w.code + "]");
    }
    json sizing = outcome.sizing;
    sizing["provenance"] = provenance(m_input.empty() ? "<flags>" : m_input, resolved);

    // Everything is computed; write the outputs (each atomically).
    if (!m_curveCsv.empty() && outcome.hasCurve) {
        writeCurveCsv(m_curveCsv, outcome);
    }
    if (!m_plot.empty() && outcome.hasCurve) {
        plot::XyPlot p;
        p.title = "Ballistic limit: " + outcome.curveLabel;
        p.xLabel = "impact speed [km/s]";
        p.yLabel = "critical diameter [mm]";
        plot::Series curve;
        curve.label = "d_c (" + outcome.curveLabel + ")";
        curve.color = {0.1, 0.3, 0.7};
        curve.width = 2.0;
        for (const auto& pt : outcome.curve.points) {
            curve.x.push_back(pt.velocityKmS);
            curve.y.push_back(units::cmToMm(pt.criticalDiameterCm));
        }
        p.series.push_back(curve);
        plot::Series threat;
        threat.label = "threat";
        threat.line = false;
        threat.color = {0.0, 0.0, 0.0};
        threat.width = 4.0;
        threat.x = {resolved["threat"]["velocity_km_s"].get<double>()};
        threat.y = {resolved["threat"]["diameter_mm"].get<double>()};
        p.series.push_back(threat);
        if (!m_overlay.empty()) {
            const json tests = io::readJsonFile(m_overlay);
            plot::Series perforated, stopped;
            perforated.label = "test: perforated (P)";
            perforated.line = false;
            perforated.color = {0.8, 0.1, 0.1};
            stopped.label = "test: not perforated (NP)";
            stopped.line = false;
            stopped.filledMarker = false;
            stopped.color = {0.1, 0.6, 0.2};
            collectShots(tests, perforated.x, perforated.y, stopped.x, stopped.y);
            p.series.push_back(perforated);
            p.series.push_back(stopped);
        }
        plot::writePlot(p, m_plot);
    }
    io::writeTextAtomically(m_output, io::jsonText(sizing, 2) + "\n");
    if (!quiet() && sizing.contains("performance")) {
        const auto& perf = sizing["performance"];
        char line[256];
        std::snprintf(line, sizeof line, "%s: d_c = %.3f mm for d = %.3f mm at %.2f km/s: %s",
                      perf["equation"].get<std::string>().c_str(),
                      perf["critical_diameter_mm"].get<double>(),
                      resolved["threat"]["diameter_mm"].get<double>(),
                      resolved["threat"]["velocity_km_s"].get<double>(),
                      perf["verdict"].get<std::string>().c_str());
        info(line);
    }
    if (!quiet() && sizing.contains("thesis_workflow")) {
        const auto& s = sizing["thesis_workflow"]["initial_standoff"];
        char buf[256];
        if (s["status"] == "solved") {
            std::snprintf(buf, sizeof buf,
                          "initial standoff (thesis eq 29): S_initial = %.2f mm with %.3f mm "
                          "plates (even split of the panel's mass)",
                          s["standoff_mm"].get<double>(), s["plate_mm"].get<double>());
            info(buf);
        } else {
            info("initial standoff (thesis eq 29): " + s["message"].get<std::string>());
        }
    }
}

} // namespace hvi::app
