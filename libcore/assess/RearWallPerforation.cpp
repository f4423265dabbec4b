#include "assess/RearWallPerforation.hpp"

#include "assess/ConnectedSets.hpp"
#include "assess/FailurePath.hpp"
#include "assess/MaterialState.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace hvi::assess {

namespace {

/// The wall's radial bins (one spacing wide, or a little more or less) and, per bin, its
/// current rear surface.
struct WallBins {
    double rMin = 0.0, width = 0.0;
    long count = 0;
    std::vector<double> surface;

    long binOf(double r) const { return static_cast<long>(std::floor((r - rMin) / width)); }
};

/// The median of `values` (0 when empty).
double median(std::vector<double> values) {
    if (values.empty()) {
        return 0.0;
    }
    const auto mid = values.begin() + static_cast<long>(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
}

/// The items of the wall as it stands (see the surface in rearWallPerforation): the joined
/// set of its alive items with the most of its own material. Its sound material joins
/// across Criteria::joinSpacings (stretched, it is still whole); failed material and the
/// particles of eroded elements only when touching (linkSpacings), so a stream of them
/// leaving the back face does not carry the wall with it.
std::vector<std::size_t> wallAsItStands(const MaterialItems& items, const ShieldLayout& layout,
                                        std::size_t wall, const Criteria& criteria) {
    std::vector<std::size_t> index;
    std::vector<double> z, r;
    std::vector<std::uint8_t> sound;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (belongsTo(items, i, wall) && items.alive[i]) {
            index.push_back(i);
            z.push_back(items.z[i]);
            r.push_back(items.r[i]);
            sound.push_back(isBodyMaterial(items, i, layout, wall) &&
                            !isFailed(items, i, layout, criteria));
        }
    }
    if (index.empty()) {
        return index;
    }
    const double s = layout.bodies[wall].spacing;
    const std::vector<std::size_t> label =
        connectedSets(z, r, criteria.linkSpacings * s, sound, criteria.joinSpacings * s);
    std::vector<double> own(index.size(), 0.0); // the wall's own mass per set, by label
    for (std::size_t k = 0; k < index.size(); ++k) {
        if (isBodyMaterial(items, index[k], layout, wall)) {
            own[label[k]] += items.mass[index[k]];
        }
    }
    const std::size_t main =
        static_cast<std::size_t>(std::max_element(own.begin(), own.end()) - own.begin());
    std::vector<std::size_t> standing;
    for (std::size_t k = 0; k < index.size(); ++k) {
        if (label[k] == main) {
            standing.push_back(index[k]);
        }
    }
    return standing;
}

/// Bulge, dent, failed material by half of the wall, and the wall's speed: the grades short
/// of perforation and whether the wall is at rest (file comment of the header). The wall is
/// its own dense material, wherever it has moved, short of what has left it: more than two
/// spacings behind its rear surface (spall) or more than its axial window in front of its
/// initial front face (ejecta). Displacements are taken relative to the median of the
/// outer quarter of the same row, so that the whole wall drifting with the momentum it took
/// (no edge supports it) is no bulge.
void gradeWallMaterial(const MaterialItems& items, const ShieldLayout& layout, std::size_t wall,
                       const Criteria& criteria, const WallBins& bins,
                       RearWallPerforation& result) {
    const BodyLayout& body = layout.bodies[wall];
    const double s = body.spacing;
    const double mid = 0.5 * (body.zFront + body.zRear);
    const double outer = body.rMin + 0.75 * (body.rMax - body.rMin);
    const double lowest = body.zFront - axialWindow(body, criteria);
    std::vector<double> rearMoved, frontMoved, rearOuter, frontOuter;
    std::vector<double> rearR0, frontR0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!isBodyMaterial(items, i, layout, wall)) {
            continue;
        }
        const bool failed = isFailed(items, i, layout, criteria);
        if (failed && items.z0[i] < mid) {
            result.failedFrontHalf = true; // eroded or failed at the struck side: a crater
        }
        const long k = bins.binOf(items.r[i]);
        if (!items.alive[i] || k < 0 || k >= bins.count ||
            items.density[i] < criteria.intactDensityRatio * body.referenceDensity ||
            items.z[i] > bins.surface[static_cast<std::size_t>(k)] + 2.0 * s ||
            items.z[i] < lowest) {
            continue; // not the wall any more
        }
        if (failed) {
            result.failedRearHalf = result.failedRearHalf || items.z0[i] >= mid;
            continue;
        }
        result.wallMaxSpeedKmS = std::max(result.wallMaxSpeedKmS, std::fabs(items.vz[i]));
        const double moved = items.z[i] - items.z0[i];
        if (items.z0[i] >= body.zRear - s) {
            (items.r0[i] >= outer ? rearOuter : rearMoved).push_back(moved);
        }
        if (items.z0[i] <= body.zFront + s) {
            (items.r0[i] >= outer ? frontOuter : frontMoved).push_back(moved);
        }
    }
    const double rearDrift = median(rearOuter), frontDrift = median(frontOuter);
    for (double m : rearMoved) {
        result.bulgeMm = std::max(result.bulgeMm, m - rearDrift);
    }
    for (double m : frontMoved) {
        result.dentMm = std::max(result.dentMm, m - frontDrift);
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

    // The current rear surface per radial bin: the rearmost item, in the bin, of the wall as
    // it stands -- the set of the wall's alive items (its material, sound or failed in place,
    // and the particles of its eroded elements still touching it) joined at their current
    // positions (Criteria::joinSpacings) that holds most of the wall's own material. A scab or
    // fragment that has left the wall is a set of its own however sound its material, so it
    // is spall, not surface; a bin where the wall has nothing left uses the initial rear face.
    const double s = body.spacing;
    const double extent = body.rMax - body.rMin;
    WallBins bins;
    bins.rMin = body.rMin;
    bins.count = std::max(1L, std::lround(extent / s));
    bins.width = extent / static_cast<double>(bins.count);
    const long count = bins.count;
    const auto n = static_cast<std::size_t>(count);
    auto binOf = [&](double r) { return bins.binOf(r); };
    const std::vector<std::size_t> standing = wallAsItStands(items, layout, wall, criteria);
    std::vector<double> surface(n, -std::numeric_limits<double>::infinity());
    for (std::size_t i : standing) {
        const long k = binOf(items.r[i]);
        if (k >= 0 && k < count) {
            auto& top = surface[static_cast<std::size_t>(k)];
            top = std::max(top, items.z[i]);
        }
    }
    for (double& top : surface) {
        if (!std::isfinite(top)) {
            top = body.zRear;
        }
    }
    bins.surface = surface;

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
                // Where it came from (the material frame, as the open columns): spall thrown
                // off the axis columns stays an axis-band failure however far it spreads.
                result.spallRadiusMm = std::max(result.spallRadiusMm, items.r0[i] + 0.5 * s);
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
    gradeWallMaterial(items, layout, wall, criteria, bins, result);
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
            result.openRadiusMm = body.rMin + static_cast<double>(k + 1) * bins.width;
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
