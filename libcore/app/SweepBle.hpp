// The ballistic limit equation's value of a swept parameter (ble-size's computation, in
// process): the critical projectile diameter at a speed, or the rear-wall thickness at which
// the given projectile is just at the limit. The sweep starts from it and plots it.
#pragma once

#include "sweep/SweepSpec.hpp"

#include <nlohmann/json.hpp>

namespace hvi::app {

/// The equation's value [mm] for the constraints at `speedKmS`; NaN when the equation has no
/// such value (no limit between 0.05 and 50 mm of wall, or a shield it does not cover).
double bleCriticalValue(const nlohmann::json& constraints, sweep::Parameter parameter,
                        double speedKmS);

} // namespace hvi::app
