#include "sweep/SweepSpec.hpp"

#include "io/JsonInput.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hvi::sweep {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The search never leaves [guess / kRangeFactor, guess * kRangeFactor]: a limit that far from
// the equation's is not a limit this shield has (or the scene is wrong).
constexpr double kRangeFactor = 4.0;

double rounded(double valueMm) {
    return std::round(valueMm * 1e4) / 1e4;
}

} // namespace

Parameter parameterFromName(const std::string& name) {
    if (name == "diameter") {
        return Parameter::Diameter;
    }
    if (name == "rear_wall") {
        return Parameter::RearWall;
    }
    throw std::invalid_argument("unknown parameter '" + name + "'");
}

const char* toString(Parameter p) {
    return p == Parameter::Diameter ? "diameter" : "rear_wall";
}

std::string panelPointer(Parameter p) {
    return p == Parameter::Diameter ? "/threat/diameter_mm" : "/panel/rear_facesheet_mm";
}

std::string constraintsPointer(Parameter p, const json& constraints) {
    if (p == Parameter::Diameter) {
        return "/threat/diameter_mm";
    }
    // Whipple shields name the rear plate a wall, sandwich panels a facesheet.
    const bool wall = constraints.is_object() && constraints.contains("shield") &&
                      constraints["shield"].contains("rear_wall_mm");
    return wall ? "/shield/rear_wall_mm" : "/shield/rear_facesheet_mm";
}

json makeSpec(const SweepRequest& r) {
    json panel = r.panel;
    panel["threat"]["velocity_km_s"] = r.speedKmS;
    json constraints = r.constraints;
    if (constraints.is_object()) {
        constraints["threat"]["velocity_km_s"] = r.speedKmS;
    }
    const double guess = rounded(r.guessMm);
    return json{
        {"id", r.id},
        {"parameter", toString(r.parameter)},
        {"speed_km_s", r.speedKmS},
        {"writer", r.writer},
        {"panel", panel},
        {"constraints", constraints},
        {"search",
         {{"guess_mm", guess},
          {"guess_source", r.guessSource},
          {"tolerance_mm", r.toleranceMm},
          {"step_factor", r.stepFactor},
          {"max_points", r.maxPoints},
          {"lowest_mm", rounded(guess / kRangeFactor)},
          {"highest_mm", rounded(guess * kRangeFactor)}}},
    };
}

SearchSettings settingsOf(const json& spec) {
    const json& s = spec.at("search");
    SearchSettings out;
    out.direction = parameterFromName(spec.at("parameter")) == Parameter::Diameter
                        ? Direction::FailsAsItGrows
                        : Direction::HoldsAsItGrows;
    out.guess = s.at("guess_mm");
    out.tolerance = s.at("tolerance_mm");
    out.stepFactor = s.at("step_factor");
    out.maxPoints = s.at("max_points");
    out.lowest = s.at("lowest_mm");
    out.highest = s.at("highest_mm");
    return out;
}

std::string pointName(const json& spec, double valueMm) {
    const char letter = parameterFromName(spec.at("parameter")) == Parameter::Diameter ? 'd' : 't';
    char buf[64];
    std::snprintf(buf, sizeof buf, "%c%.4f", letter, rounded(valueMm));
    return buf;
}

json pointPanel(const json& spec, double valueMm) {
    json panel = spec.at("panel");
    panel[json::json_pointer(panelPointer(parameterFromName(spec.at("parameter"))))] =
        rounded(valueMm);
    char speed[32];
    std::snprintf(speed, sizeof speed, "%g", spec.at("speed_km_s").get<double>());
    panel["id"] = spec.at("id").get<std::string>() + "-v" + speed + "-" + pointName(spec, valueMm);
    return panel;
}

std::vector<PointRecord> readPoints(const fs::path& dir, const json& spec) {
    std::vector<PointRecord> out;
    const fs::path points = dir / "points";
    if (!fs::is_directory(points)) {
        return out;
    }
    const json::json_pointer at(panelPointer(parameterFromName(spec.at("parameter"))));
    for (const auto& entry : fs::directory_iterator(points)) {
        const fs::path verdictFile = entry.path() / "verdict.json";
        if (!fs::is_regular_file(verdictFile)) {
            continue; // not run yet, or interrupted
        }
        const json panel = io::readJsonFile((entry.path() / "panel.json").string());
        const json verdict = io::readJsonFile(verdictFile.string());
        if (!verdict.contains("verdict") || !verdict["verdict"].is_string()) {
            throw std::runtime_error(verdictFile.string() + ": no /verdict");
        }
        PointRecord p;
        p.name = entry.path().filename().string();
        p.point.value = panel.at(at).get<double>();
        p.point.perforated = verdict["verdict"] == "P";
        p.final = verdict.value("verdict_final", true);
        p.axisOnly = verdict.value("axis_band_only", false);
        out.push_back(p);
    }
    std::sort(out.begin(), out.end(), [](const PointRecord& a, const PointRecord& b) {
        return a.point.value < b.point.value;
    });
    return out;
}

json criticalDocument(const json& spec, const SearchStep& step,
                      const std::vector<PointRecord>& points) {
    json runs = json::array();
    for (const auto& p : points) {
        runs.push_back({{"value_mm", p.point.value},
                        {"verdict", p.point.perforated ? "P" : "NP"},
                        {"verdict_final", p.final},
                        {"axis_band_only", p.axisOnly},
                        {"run", p.name}});
    }
    const auto orNull = [](const std::optional<double>& v) { return v ? json(*v) : json(); };
    json critical = nullptr;
    if (step.failSide && step.holdSide) {
        critical = 0.5 * (*step.failSide + *step.holdSide);
    }
    return json{
        {"id", spec.at("id")},
        {"parameter", spec.at("parameter")},
        {"speed_km_s", spec.at("speed_km_s")},
        {"state", toString(step.state)},
        {"critical_mm", critical},
        {"fail_side_mm", orNull(step.failSide)},
        {"hold_side_mm", orNull(step.holdSide)},
        {"held_beyond_fail_side_mm", step.outOfOrder},
        {"guess_mm", spec.at("search").at("guess_mm")},
        {"guess_source", spec.at("search").at("guess_source")},
        {"runs", runs},
    };
}

} // namespace hvi::sweep
