#include "app/HviSweepTool.hpp"

#include "app/SweepBle.hpp"
#include "io/AtomicOutput.hpp"
#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"
#include "plot/XyPlot.hpp"
#include "sweep/SweepResults.hpp"
#include "sweep/SweepSpec.hpp"
#include "validation/CaseInputs.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace hvi::app {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The equation's curve is drawn over this speed range [km/s] at this step.
constexpr double kCurveFromKmS = 1.0, kCurveToKmS = 15.0, kCurveStepKmS = 0.25;

plot::Series markers(const std::string& label, plot::Rgb color, bool filled) {
    plot::Series s;
    s.label = label;
    s.line = false;
    s.filledMarker = filled;
    s.color = color;
    s.width = 4.0;
    return s;
}

/// The sweep's critical values with their brackets, the equation's curve and the tests.
plot::XyPlot sweepPlot(const std::vector<sweep::SpeedResult>& results) {
    const json& spec = results.front().spec;
    const auto parameter = sweep::parameterFromName(spec.at("parameter"));
    plot::XyPlot p;
    p.title = "Simulated ballistic limit: " + spec.at("id").get<std::string>();
    p.xLabel = "impact speed [km/s]";
    p.yLabel = parameter == sweep::Parameter::Diameter ? "critical projectile diameter [mm]"
                                                       : "rear wall at the limit [mm]";
    plot::Series ble;
    ble.label = "ballistic limit equation";
    ble.color = {0.1, 0.3, 0.7};
    ble.width = 2.0;
    for (double v = kCurveFromKmS; v <= kCurveToKmS + 1e-9; v += kCurveStepKmS) {
        const double x = bleCriticalValue(spec.at("constraints"), parameter, v);
        if (std::isfinite(x)) {
            ble.x.push_back(v);
            ble.y.push_back(x);
        }
    }
    p.series.push_back(ble);
    plot::Series critical = markers("hydrocode: limit (bracket)", {0.0, 0.0, 0.0}, true);
    for (const auto& r : results) {
        const json& c = r.critical;
        const double v = c.at("speed_km_s");
        if (!c.at("fail_side_mm").is_null() && !c.at("hold_side_mm").is_null()) {
            plot::Series bracket;
            bracket.color = {0.0, 0.0, 0.0};
            bracket.x = {v, v};
            bracket.y = {c["fail_side_mm"].get<double>(), c["hold_side_mm"].get<double>()};
            p.series.push_back(bracket);
        }
        if (c.at("critical_mm").is_number()) {
            critical.x.push_back(v);
            critical.y.push_back(c["critical_mm"]);
        }
    }
    p.series.push_back(critical);
    plot::Series perforated = markers("test: P", {0.8, 0.1, 0.1}, true);
    plot::Series held = markers("test: NP", {0.1, 0.6, 0.2}, false);
    for (const auto& t : sweep::testsOfShield(spec)) {
        (t.perforated ? perforated : held).x.push_back(t.speedKmS);
        (t.perforated ? perforated : held).y.push_back(t.valueMm);
    }
    p.series.push_back(perforated);
    p.series.push_back(held);
    return p;
}

} // namespace

HviSweepTool::HviSweepTool()
    : tool::Tool("hvi-sweep", "The hydrocode's ballistic limit: bracket the projectile "
                              "diameter or rear-wall thickness at which the simulated verdict "
                              "flips (workflows/sweep.mk runs the points)") {}

void HviSweepTool::addOptions(CLI::App& app) {
    app.add_option("action", m_action, "init | next | report")
        ->required()
        ->check(CLI::IsMember({"init", "next", "report"}));
    app.add_option("dir", m_dir, "next: the sweep directory of one speed");
    app.add_option("--case", m_case, "init: a validation case id (hvi-validate list)");
    app.add_option("--panel", m_panel, "init: the scene writer's input (instead of --case)");
    app.add_option("--writer", m_writer, "init: foam2layers or hcomb2rings (with --panel)")
        ->check(CLI::IsMember({"foam2layers", "hcomb2rings"}));
    app.add_option("--constraints", m_constraints,
                   "init: ble-size's constraints of the same shield (the start and the curve)");
    app.add_option("--parameter", m_parameter, "init: diameter (default) or rear_wall")
        ->check(CLI::IsMember({"diameter", "rear_wall"}));
    app.add_option("--speed-km-s", m_speed, "init: impact speed [km/s]")
        ->check(CLI::PositiveNumber);
    app.add_option("--tolerance-mm", m_tolerance,
                   "init: bracket width at which the search stops [mm] (default 0.1, >= 0.001)")
        ->check(CLI::PositiveNumber);
    app.add_option("--step-factor", m_stepFactor,
                   "init: outward step while the verdict has not flipped (default 1.25, > 1)")
        ->check(CLI::PositiveNumber);
    app.add_option("--max-points", m_maxPoints, "init: runs before giving up (default 12)")
        ->check(CLI::Range(2, 100));
    app.add_option("--out-dir", m_outDir, "init: the sweep directory; report: the speeds' parent");
    app.add_option("-o,--output", m_output, "report: the CSV ('-' = stdout)");
    app.add_option("--plot", m_plot, "report: also draw the limit (.svg or .png)");
}

void HviSweepTool::execute() {
    if (m_action == "init") {
        init();
    } else if (m_action == "next") {
        next();
    } else {
        report();
    }
}

void HviSweepTool::init() {
    if (m_outDir.empty() || !(m_speed > 0.0)) {
        throw InputError("<flags>", m_outDir.empty() ? "/out_dir" : "/speed_km_s",
                         "init needs --out-dir and --speed-km-s", "both flags");
    }
    if (m_tolerance < 1e-3 || !(m_stepFactor > 1.0)) {
        throw InputError("<flags>", m_tolerance < 1e-3 ? "/tolerance_mm" : "/step_factor",
                         "out of range", "tolerance >= 0.001 mm, step factor > 1");
    }
    sweep::SweepRequest r;
    if (!m_case.empty()) {
        const validation::Case* c = nullptr;
        try {
            c = &validation::findCase(m_case);
        } catch (const std::invalid_argument& e) {
            throw InputError("<flags>", "/case", e.what(), "an id that 'hvi-validate list' prints");
        }
        r.id = c->id;
        r.panel = validation::panelInput(*c);
        r.writer = validation::sceneWriterOf(*c);
        r.constraints = validation::bleConstraints(*c);
    } else if (!m_panel.empty() && !m_writer.empty()) {
        r.panel = io::readJsonFile(m_panel);
        r.id = r.panel.value("id", fs::path(m_panel).stem().string());
        r.writer = m_writer;
        r.constraints = m_constraints.empty() ? json() : io::readJsonFile(m_constraints);
    } else {
        throw InputError("<flags>", "/case", "no shield given",
                         "--case ID, or --panel and --writer");
    }
    r.parameter = sweep::parameterFromName(m_parameter);
    r.speedKmS = m_speed;
    r.toleranceMm = m_tolerance;
    r.stepFactor = m_stepFactor;
    r.maxPoints = m_maxPoints;
    const double ble = bleCriticalValue(r.constraints, r.parameter, m_speed);
    const json::json_pointer own(sweep::panelPointer(r.parameter));
    if (!r.panel.contains(own)) {
        throw InputError(m_panel.empty() ? "<case>" : m_panel, own.to_string(), "is missing",
                         "the swept value in the scene writer's input");
    }
    r.guessMm = std::isfinite(ble) ? ble : r.panel.at(own).get<double>();
    r.guessSource = std::isfinite(ble) ? "ballistic limit equation" : "the panel's own value";
    const json spec = sweep::makeSpec(r);
    const fs::path file = fs::path(m_outDir) / "sweep.json";
    if (fs::exists(file) && io::readJsonFile(file.string()) != spec) {
        throw InputError(file.string(), "", "holds another sweep",
                         "a new --out-dir, or the same settings as before");
    }
    fs::create_directories(m_outDir);
    io::writeTextAtomically(file, io::jsonText(spec, 2) + "\n");
    info(spec.at("id").get<std::string>() + " at " + std::to_string(m_speed) + " km/s: " +
         m_parameter + " from " + std::to_string(r.guessMm) + " mm (" + r.guessSource + ")");
}

void HviSweepTool::next() {
    if (m_dir.empty()) {
        throw InputError("<flags>", "/dir", "next needs the sweep directory", "hvi-sweep next DIR");
    }
    const fs::path dir(m_dir);
    const json spec = io::readJsonFile((dir / "sweep.json").string());
    std::vector<sweep::PointRecord> records;
    try {
        records = sweep::readPoints(dir, spec);
    } catch (const std::exception& e) {
        throw RuntimeFailure(e.what());
    }
    std::vector<sweep::SearchPoint> points;
    for (const auto& r : records) {
        points.push_back(r.point);
    }
    const sweep::SearchStep step = sweep::nextStep(sweep::settingsOf(spec), points);
    if (step.state != sweep::SearchState::RunNext) {
        io::writeTextAtomically(dir / "critical.json",
                                io::jsonText(sweep::criticalDocument(spec, step, records), 2) +
                                    "\n");
        info(dir.string() + ": " + sweep::toString(step.state) + " after " +
             std::to_string(points.size()) + " runs");
        return;
    }
    const fs::path point = dir / "points" / sweep::pointName(spec, step.next);
    fs::create_directories(point);
    if (!fs::exists(point / "panel.json")) {
        io::writeTextAtomically(point / "writer", spec.at("writer").get<std::string>() + "\n");
        io::writeTextAtomically(point / "panel.json",
                                io::jsonText(sweep::pointPanel(spec, step.next), 2) + "\n");
    }
    info(dir.string() + ": run " + std::to_string(points.size() + 1) + ", " +
         point.filename().string());
    std::cout << point.string() << "\n";
}

void HviSweepTool::report() {
    if (m_outDir.empty() || m_output.empty()) {
        throw InputError("<flags>", m_outDir.empty() ? "/out_dir" : "/output",
                         "report needs --out-dir and -o", "both flags");
    }
    std::vector<sweep::SpeedResult> results;
    try {
        results = sweep::readResults(m_outDir);
    } catch (const std::runtime_error& e) {
        throw InputError(m_outDir, "", e.what(), "a sweep directory with finished speeds");
    }
    const std::string csv = sweep::resultsCsv(results);
    if (m_output == "-") {
        std::cout << csv;
    } else {
        io::writeTextAtomically(m_output, csv);
    }
    if (!m_plot.empty()) {
        plot::writePlot(sweepPlot(results), m_plot);
    }
}

} // namespace hvi::app
