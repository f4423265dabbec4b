#include "app/SweepBle.hpp"

#include "app/BleSizing.hpp"
#include "ble/RootFinding.hpp"
#include "io/JsonInput.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hvi::app {

using nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The wall thicknesses searched for the equation's limit [mm].
constexpr double kThinnestWallMm = 0.05, kThickestWallMm = 50.0;

double criticalDiameterMm(json constraints) {
    constraints["mode"] = "performance";
    const json resolved = io::withSchemaDefaults(constraints, "constraints");
    try {
        const json sizing = computeSizing(resolved, "<sweep>").sizing;
        if (!sizing.contains("performance")) {
            return kNaN;
        }
        return sizing["performance"].value("critical_diameter_mm", kNaN);
    } catch (const std::exception&) {
        return kNaN; // outside the equation's domain
    }
}

} // namespace

double bleCriticalValue(const json& constraints, sweep::Parameter parameter, double speedKmS) {
    if (!constraints.is_object()) {
        return kNaN;
    }
    json c = constraints;
    c["threat"]["velocity_km_s"] = speedKmS;
    if (parameter == sweep::Parameter::Diameter) {
        return criticalDiameterMm(c);
    }
    const double diameter = c["threat"]["diameter_mm"];
    const json::json_pointer wall(sweep::constraintsPointer(parameter, c));
    const auto excess = [&](double t) {
        c[wall] = t;
        return criticalDiameterMm(c) - diameter; // grows with the wall
    };
    const ble::RootResult root = ble::brentRoot(excess, kThinnestWallMm, kThickestWallMm, 1e-4);
    return root.bracketed && std::isfinite(root.fx) ? root.x : kNaN;
}

} // namespace hvi::app
