#include "sweep/SweepResults.hpp"

#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"
#include "sweep/SweepSpec.hpp"
#include "validation/ValidationCase.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hvi::sweep {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// Tests of one series differ in their nominal plates by a few hundredths of a mm.
constexpr double kSameSize = 0.02;

bool close(double a, double b) {
    return std::abs(a - b) <= kSameSize * std::max(a, b);
}

std::string cell(const json& v) {
    if (v.is_null()) {
        return "";
    }
    std::ostringstream s;
    if (v.is_number()) {
        s << v.get<double>();
    } else if (v.is_string()) {
        s << v.get<std::string>();
    } else {
        s << io::jsonText(v);
    }
    return s.str();
}

// A test is of the swept shield only if it used the same alloys: the material a panel names for
// a part (its own key, else the panel's one "material"), when it names one, must be the test's.
bool sameMaterial(const json& panel, const char* key, const std::string& tested) {
    const std::string named = panel.value(key, panel.value("material", std::string()));
    return named.empty() || named == tested;
}

bool sameCoreMaterial(const json& panel, const std::string& tested) {
    const std::string named =
        panel.value("foil_material", panel.value("core_material", std::string()));
    return named.empty() || named == tested;
}

validation::Shield shieldOf(const json& panel) {
    if (panel.contains("cell_size_mm")) {
        return validation::Shield::Honeycomb;
    }
    return panel.value("type", "") == "whipple" ? validation::Shield::Whipple
                                                : validation::Shield::Foam;
}

} // namespace

std::vector<SpeedResult> readResults(const fs::path& outDir) {
    std::vector<SpeedResult> out;
    if (fs::is_directory(outDir)) {
        for (const auto& entry : fs::directory_iterator(outDir)) {
            const fs::path spec = entry.path() / "sweep.json";
            const fs::path critical = entry.path() / "critical.json";
            if (fs::is_regular_file(spec) && fs::is_regular_file(critical)) {
                out.push_back(
                    {io::readJsonFile(spec.string()), io::readJsonFile(critical.string())});
            }
        }
    }
    if (out.empty()) {
        throw std::runtime_error(outDir.string() + ": no finished speed (no */critical.json)");
    }
    std::sort(out.begin(), out.end(), [](const SpeedResult& a, const SpeedResult& b) {
        return a.spec.at("speed_km_s").get<double>() < b.spec.at("speed_km_s").get<double>();
    });
    return out;
}

std::string resultsCsv(const std::vector<SpeedResult>& results) {
    std::ostringstream s;
    s << "speed_km_s,parameter,state,critical_mm,fail_side_mm,hold_side_mm,runs,guess_mm,"
         "held_beyond_fail_side_mm\n";
    for (const auto& r : results) {
        const json& c = r.critical;
        std::string beyond;
        for (const auto& v : c.at("held_beyond_fail_side_mm")) {
            beyond += (beyond.empty() ? "" : ";") + cell(v);
        }
        s << cell(c.at("speed_km_s")) << ',' << cell(c.at("parameter")) << ','
          << cell(c.at("state")) << ',' << cell(c.at("critical_mm")) << ','
          << cell(c.at("fail_side_mm")) << ',' << cell(c.at("hold_side_mm")) << ','
          << c.at("runs").size() << ',' << cell(c.at("guess_mm")) << ',' << beyond << '\n';
    }
    return s.str();
}

std::vector<TestShot> testsOfShield(const json& spec) {
    const json& panel = spec.at("panel").at("panel");
    const double diameter = spec.at("panel").at("threat").at("diameter_mm");
    const bool sweepsDiameter = parameterFromName(spec.at("parameter")) == Parameter::Diameter;
    const validation::Shield shield = shieldOf(panel);
    std::vector<TestShot> out;
    for (const auto& c : validation::allCases()) {
        const bool fixedMatches =
            sweepsDiameter ? close(c.rear.thicknessMm, panel.at("rear_facesheet_mm").get<double>())
                           : close(c.diameterMm, diameter);
        if (c.shield != shield || !fixedMatches ||
            !close(c.front.thicknessMm, panel.at("front_facesheet_mm").get<double>()) ||
            !close(c.gapMm, panel.at("core_thickness_mm").get<double>()) ||
            !sameMaterial(panel, "front_facesheet_material", c.front.material) ||
            !sameMaterial(panel, "rear_facesheet_material", c.rear.material) ||
            !sameCoreMaterial(panel, c.coreMaterial)) {
            continue;
        }
        out.push_back({c.id, c.velocityKmS, sweepsDiameter ? c.diameterMm : c.rear.thicknessMm,
                       c.result == "P"});
    }
    return out;
}

} // namespace hvi::sweep
