#include "assess/RearWallDamageProfile.hpp"

#include "assess/MaterialState.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::assess {

std::optional<RearWallDamageProfile> rearWallDamageProfile(const MaterialItems& items,
                                                           const ShieldLayout& layout,
                                                           const Criteria& criteria) {
    if (!layout.rearWall) {
        return std::nullopt;
    }
    const std::size_t wall = *layout.rearWall;
    const BodyLayout& body = layout.bodies[wall];
    const double extent = body.rMax - body.rMin;
    const long count = std::max(1L, std::lround(extent / body.spacing));
    const double w = extent / static_cast<double>(count);
    const auto n = static_cast<std::size_t>(count);
    std::vector<double> mass(n, 0.0), failed(n, 0.0), damage(n, 0.0);
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!isBodyMaterial(items, i, layout, wall)) {
            continue;
        }
        const long k = static_cast<long>(std::floor((items.r0[i] - body.rMin) / w));
        if (k < 0 || k >= count) {
            continue;
        }
        const auto kk = static_cast<std::size_t>(k);
        const double m = items.mass[i];
        mass[kk] += m;
        if (isFailed(items, i, layout, criteria)) {
            failed[kk] += m;
        }
        damage[kk] += m * (items.alive[i] ? std::clamp(items.damage[i], 0.0, 1.0) : 1.0);
    }
    RearWallDamageProfile profile;
    profile.timeUs = items.timeUs;
    for (std::size_t k = 0; k < n; ++k) {
        profile.radiusMm.push_back(body.rMin + (static_cast<double>(k) + 0.5) * w);
        profile.failedFraction.push_back(mass[k] > 0.0 ? failed[k] / mass[k] : 0.0);
        profile.meanDamage.push_back(mass[k] > 0.0 ? damage[k] / mass[k] : 0.0);
    }
    return profile;
}

} // namespace hvi::assess
