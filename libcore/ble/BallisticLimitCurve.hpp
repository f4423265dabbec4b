// Ballistic limit curve: critical diameter against impact velocity for any shield, sampled
// uniformly in velocity, with the regime kept per point so a plot can mark the transitions.
//
// The shield is passed as a callable d_c(V) (e.g. a lambda binding a WhippleShield and a
// Threat whose velocity it overrides), so one sampler serves every BLE in hvi::ble.
// Units: km/s, cm.
#pragma once

#include "ble/Types.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace hvi::ble {

struct BallisticLimitPoint {
    double velocityKmS = 0.0;
    double criticalDiameterCm = 0.0;
    Regime regime = Regime::Hypervelocity;
};

struct BallisticLimitCurve {
    std::vector<BallisticLimitPoint> points;
    /// Warnings of all points, one per code (the first message seen for it).
    std::vector<ValidityWarning> warnings;
};

using CriticalDiameterAtVelocity = std::function<CriticalDiameterResult(double velocityKmS)>;

/// `count` >= 2 points from vMinKmS to vMaxKmS inclusive (0 < vMin < vMax).
BallisticLimitCurve sampleBallisticLimitCurve(const CriticalDiameterAtVelocity& dcAtVelocity,
                                              double vMinKmS = 0.5, double vMaxKmS = 15.0,
                                              std::size_t count = 100);

} // namespace hvi::ble
