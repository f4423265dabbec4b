#include "assess/RearWallPerforation.hpp"

#include "assess/FailurePath.hpp"
#include "assess/MaterialState.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace hvi::assess {

namespace {

/// Bulge, dent, failed material by half of the wall, and the wall's speed: the grades short
/// of perforation and whether the wall is at rest (file comment of the header).
void gradeWallMaterial(const MaterialItems& items, const ShieldLayout& layout, std::size_t wall,
                       const Criteria& criteria, RearWallPerforation& result) {
    const BodyLayout& body = layout.bodies[wall];
    const double s = body.spacing;
    const double mid = 0.5 * (body.zFront + body.zRear);
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!isBodyMaterial(items, i, layout, wall)) {
            continue;
        }
        const bool failed = isFailed(items, i, layout, criteria);
        const bool inPlace = isInPlace(items, i, layout, criteria);
        if (failed && items.z0[i] < mid) {
            result.failedFrontHalf = true; // eroded or failed at the struck side: a crater
        }
        if (!inPlace) {
            continue;
        }
        if (failed && items.z0[i] >= mid) {
            result.failedRearHalf = true;
        }
        result.wallMaxSpeedKmS = std::max(result.wallMaxSpeedKmS, std::fabs(items.vz[i]));
        const double moved = items.z[i] - items.z0[i];
        if (items.z0[i] >= body.zRear - s) {
            result.bulgeMm = std::max(result.bulgeMm, moved);
        }
        if (items.z0[i] <= body.zFront + s) {
            result.dentMm = std::max(result.dentMm, moved);
        }
    }
}

} // namespace

double axisBandMm(const ShieldLayout& layout, std::size_t wall, const Criteria& criteria) {
    const BodyLayout& body = layout.bodies[wall];
    if (!layout.axisymmetric || body.rMin > 0.0) {
        return -1.0;
    }
    const double extent = body.rMax - body.rMin;
    const double columns = std::max(1.0, std::round(extent / body.spacing));
    return criteria.axisBandSpacings * std::max(body.spacing, extent / columns) * (1.0 + 1e-9);
}

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

    // (b) Material beyond the surface, moving outward; detached spall; what still approaches.
    double crossingRadius = 0.0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!items.alive[i] || items.body[i] < 0) {
            continue;
        }
        const long k = binOf(items.r[i]);
        if (k < 0 || k >= count) {
            continue;
        }
        const double beyond = items.z[i] - surface[static_cast<std::size_t>(k)];
        const auto ib = static_cast<std::size_t>(items.body[i]);
        // Only bodies that started in front of the rear wall (not a witness plate behind it).
        const bool frontBody = ib != wall && layout.bodies[ib].zFront < body.zRear;
        if (frontBody && beyond <= 0.0 && items.vz[i] > criteria.restSpeedKmS) {
            ++result.approachingItems;
            result.approachingMaxSpeedKmS = std::max(result.approachingMaxSpeedKmS, items.vz[i]);
        }
        if (items.vz[i] <= 0.0) {
            continue;
        }
        if (ib == wall) {
            if (beyond > 2.0 * s) { // only detached material is beyond the surface
                ++result.spallItems;
                result.spallMassMg += items.mass[i];
                result.spallRadiusMm = std::max(result.spallRadiusMm, items.r[i] + 0.5 * s);
            }
            continue;
        }
        if (frontBody && beyond > s) {
            ++result.crossingItems;
            result.crossingMassMg += items.mass[i];
            crossingRadius = std::max(crossingRadius, items.r[i]);
        }
    }
    const auto minItems = static_cast<std::size_t>(std::max(1, criteria.minCrossingItems));
    result.materialCrossed = result.crossingItems >= minItems;
    result.detachedSpall = result.spallItems >= minItems;
    result.spallAxisConfined =
        result.detachedSpall && result.spallRadiusMm <= axisBandMm(layout, wall, criteria);
    gradeWallMaterial(items, layout, wall, criteria, result);
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
        result.axisConfined = outer <= axisBandMm(layout, wall, criteria);
    }
    return result;
}

} // namespace hvi::assess
