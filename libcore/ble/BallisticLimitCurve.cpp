// Ballistic limit curve sampler; see BallisticLimitCurve.hpp.
#include "ble/BallisticLimitCurve.hpp"

#include "ble/ArgumentChecks.hpp"

#include <stdexcept>
#include <string>

namespace hvi::ble {

BallisticLimitCurve sampleBallisticLimitCurve(const CriticalDiameterAtVelocity& dcAtVelocity,
                                              double vMinKmS, double vMaxKmS, std::size_t count) {
    // V = 0 is excluded: every ballistic branch scales as V^(-2/3).
    detail::requirePositive("curve minimum velocity [km/s]", vMinKmS);
    if (!(vMaxKmS > vMinKmS) || count < 2 || !dcAtVelocity) {
        throw std::invalid_argument("hvi::ble: ballistic limit curve needs vMax > vMin, "
                                    ">= 2 points and a d_c function (got vMin " +
                                    std::to_string(vMinKmS) + ", vMax " + std::to_string(vMaxKmS) +
                                    ", " + std::to_string(count) + " points)");
    }
    BallisticLimitCurve curve;
    curve.points.reserve(count);
    const double step = (vMaxKmS - vMinKmS) / static_cast<double>(count - 1);
    for (std::size_t i = 0; i < count; ++i) {
        // The last point is set exactly so the curve ends at vMax despite round-off.
        const double v = i + 1 == count ? vMaxKmS : vMinKmS + step * static_cast<double>(i);
        CriticalDiameterResult r = dcAtVelocity(v);
        curve.points.push_back({v, r.criticalDiameterCm, r.regime});
        for (auto& w : r.warnings) {
            if (!hasWarning(curve.warnings, w.code)) {
                curve.warnings.push_back(std::move(w));
            }
        }
    }
    return curve;
}

} // namespace hvi::ble
