// One speed of a simulated-ballistic-limit sweep on disk (workflows/sweep.mk):
//
//   DIR/sweep.json            the spec: the shield's scene-writer input at this speed, the
//                             writer, the parameter searched, the search settings, and the
//                             ballistic limit equation's value of the parameter (the guess);
//   DIR/points/<name>/        one run per value: panel.json and writer (written here), then
//                             scene.json, run.h5, verdict.json (written by the workflow);
//   DIR/critical.json         the result, once the search stops.
//
// The parameter is the projectile diameter (/threat/diameter_mm of the writer's input) or the
// rear wall's thickness (/panel/rear_facesheet_mm). Point names carry the value to 1e-4 mm
// ("d3.1800", "t4.7800"), so the tolerance must be well above that. Units: mm, km/s.
#pragma once

#include "sweep/Bisection.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hvi::sweep {

enum class Parameter { Diameter, RearWall };

/// "diameter" or "rear_wall"; throws std::invalid_argument for another name.
Parameter parameterFromName(const std::string& name);
const char* toString(Parameter p);

/// The parameter's JSON pointer in the scene writer's input and in ble-size's constraints.
std::string panelPointer(Parameter p);
std::string constraintsPointer(Parameter p, const nlohmann::json& constraints);

struct SweepRequest {
    std::string id;             ///< the shield's name, used in point ids
    nlohmann::json panel;       ///< the scene writer's input (any speed)
    std::string writer;         ///< "foam2layers" or "hcomb2rings"
    nlohmann::json constraints; ///< ble-size's constraints of the same shield, or null
    Parameter parameter = Parameter::Diameter;
    double speedKmS = 0.0;
    double guessMm = 0.0;    ///< where the search starts (the BLE value, or the panel's)
    std::string guessSource; ///< what the guess is
    double toleranceMm = 0.1;
    double stepFactor = 1.25;
    int maxPoints = 12;
};

/// The sweep.json document.
nlohmann::json makeSpec(const SweepRequest& request);

/// The search settings a spec holds.
SearchSettings settingsOf(const nlohmann::json& spec);

/// A point's directory name for a value.
std::string pointName(const nlohmann::json& spec, double valueMm);

/// The scene writer's input of the point at a value.
nlohmann::json pointPanel(const nlohmann::json& spec, double valueMm);

struct PointRecord {
    SearchPoint point;
    std::string name;
    bool final = true;     ///< the verdict's verdict_final
    bool axisOnly = false; ///< a P resting on the axis band alone
};

/// The points of DIR with a verdict.json, by increasing value. Throws std::runtime_error naming the
/// file when a verdict or panel cannot be read.
std::vector<PointRecord> readPoints(const std::filesystem::path& dir, const nlohmann::json& spec);

/// The critical.json document of a finished search.
nlohmann::json criticalDocument(const nlohmann::json& spec, const SearchStep& step,
                                const std::vector<PointRecord>& points);

} // namespace hvi::sweep
