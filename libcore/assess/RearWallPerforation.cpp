#include "assess/RearWallPerforation.hpp"

#include "assess/FailurePath.hpp"
#include "assess/MaterialState.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace hvi::assess {

std::optional<RearWallPerforation> rearWallPerforation(const MaterialItems& items,
                                                       const ShieldLayout& layout,
                                                       const Criteria& criteria) {
    if (!layout.rearWall) {
        return std::nullopt;
    }
    const std::size_t wall = *layout.rearWall;
    const BodyLayout& body = layout.bodies[wall];
    RearWallPerforation result;

    // (a) Through-thickness failure.
    const FailurePath path = failurePath(items, wall, layout, criteria);
    result.throughThicknessFailure = path.crosses;
    result.failedItems = path.failedItems;

    // The current rear surface per radial bin: the top of the wall's contiguous material in
    // the bin (failed or not, gaps no wider than the link distance), counted from the
    // rearmost item of the wall's own material (an FE wall's elements) that has not failed,
    // or from the item nearest the wall's mid-plane where all have. Failed wall material
    // still in place is wall, and so are the particles of eroded elements that stay in
    // contact with it; a fragment that has left it (detached spall, front-face ejecta, the
    // particles of eroded elements flying off, however sound) is not.
    const double s = body.spacing;
    const double link = criteria.linkSpacings * s;
    const double extent = body.rMax - body.rMin;
    const long count = std::max(1L, std::lround(extent / s));
    const double w = extent / static_cast<double>(count);
    const auto n = static_cast<std::size_t>(count);
    auto binOf = [&](double r) -> long {
        return static_cast<long>(std::floor((r - body.rMin) / w));
    };
    std::vector<std::vector<double>> wallZ(n);
    std::vector<double> topSound(n, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!belongsTo(items, i, wall) || !items.alive[i]) {
            continue;
        }
        const long k = binOf(items.r[i]);
        if (k < 0 || k >= count) {
            continue;
        }
        const auto kk = static_cast<std::size_t>(k);
        wallZ[kk].push_back(items.z[i]);
        if (isBodyMaterial(items, i, layout, wall) && !isFailed(items, i, layout, criteria)) {
            topSound[kk] = std::max(topSound[kk], items.z[i]);
        }
    }
    const double midPlane = 0.5 * (body.zFront + body.zRear);
    std::vector<double> surface(n, body.zRear);
    for (std::size_t k = 0; k < n; ++k) {
        auto& zs = wallZ[k];
        if (zs.empty()) {
            continue; // nothing left here: the initial rear face
        }
        std::sort(zs.begin(), zs.end());
        std::size_t j = 0;
        if (std::isfinite(topSound[k])) {
            j = static_cast<std::size_t>(std::find(zs.begin(), zs.end(), topSound[k]) - zs.begin());
        } else {
            for (std::size_t m = 1; m < zs.size(); ++m) {
                if (std::fabs(zs[m] - midPlane) < std::fabs(zs[j] - midPlane)) {
                    j = m;
                }
            }
        }
        while (j + 1 < zs.size() && zs[j + 1] - zs[j] <= link) {
            ++j;
        }
        surface[k] = zs[j];
    }

    // (b) Material beyond the surface, moving outward.
    double crossingRadius = 0.0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!items.alive[i] || items.vz[i] <= 0.0 || items.body[i] < 0) {
            continue;
        }
        const long k = binOf(items.r[i]);
        if (k < 0 || k >= count) {
            continue;
        }
        const double beyond = items.z[i] - surface[static_cast<std::size_t>(k)];
        const auto ib = static_cast<std::size_t>(items.body[i]);
        if (ib == wall) {
            if (beyond > 2.0 * s) { // only detached material is beyond the surface
                result.detachedSpall = true;
            }
            continue;
        }
        // Only bodies that started in front of the rear wall (not a witness plate behind it).
        if (layout.bodies[ib].zFront >= body.zRear) {
            continue;
        }
        if (beyond > s) {
            ++result.crossingItems;
            result.crossingMassMg += items.mass[i];
            crossingRadius = std::max(crossingRadius, items.r[i]);
        }
    }
    result.materialCrossed =
        result.crossingItems >= static_cast<std::size_t>(std::max(1, criteria.minCrossingItems));
    result.perforated = result.throughThicknessFailure || result.materialCrossed;

    // Open columns, in the material frame: every item of the wall's material in the bin failed.
    std::vector<std::size_t> itemsIn(n, 0), failedIn(n, 0);
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!isBodyMaterial(items, i, layout, wall)) {
            continue;
        }
        const long k = binOf(items.r0[i]);
        if (k < 0 || k >= count) {
            continue;
        }
        ++itemsIn[static_cast<std::size_t>(k)];
        if (isFailed(items, i, layout, criteria)) {
            ++failedIn[static_cast<std::size_t>(k)];
        }
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (itemsIn[k] > 0 && failedIn[k] == itemsIn[k]) {
            ++result.openColumns;
            result.openRadiusMm = body.rMin + static_cast<double>(k + 1) * w;
        }
    }
    if (result.perforated) {
        double outer = result.openRadiusMm;
        if (result.throughThicknessFailure) {
            outer = std::max(outer, std::min(path.pathRadiusMm + 0.5 * s, body.rMax));
        }
        if (result.materialCrossed) {
            outer = std::max(outer, crossingRadius + 0.5 * s);
        }
        result.perforationRadiusMm = outer;
        // The band is a number of columns: where the plate's width is not a whole number of
        // spacings its columns are a little wider (or narrower) than the spacing.
        const double band = criteria.axisBandSpacings * std::max(s, w);
        result.axisConfined =
            layout.axisymmetric && body.rMin <= 0.0 && outer <= band * (1.0 + 1e-9);
    }
    return result;
}

} // namespace hvi::assess
