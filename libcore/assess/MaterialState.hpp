// Failed and intact: the two judgements of one item every metric is built on (definitions in
// Criteria.hpp and docs/metrics.md).
#pragma once

#include "assess/Criteria.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/ShieldLayout.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::assess {

/// Deleted or eroded, fully damaged, or below the density cut-off.
inline bool isFailed(const MaterialItems& items, std::size_t i, const ShieldLayout& layout,
                     const Criteria& criteria) {
    if (!items.alive[i] || items.damage[i] >= criteria.failedDamage) {
        return true;
    }
    const double rhoRef = layout.bodies[static_cast<std::size_t>(items.body[i])].referenceDensity;
    return items.density[i] < criteria.failedDensityRatio * rhoRef;
}

/// How far (axially) intact plate material may have moved from where it started [mm].
inline double axialWindow(const BodyLayout& body, const Criteria& criteria) {
    return std::max(criteria.axialWindowThicknesses * body.thickness(), 2.0 * body.spacing);
}

/// Still where its plate is: in the calculation, dense (>= intactDensityRatio * reference)
/// and near its initial z. Failed material still in place (a torn, rolled hole lip) is in
/// place; debris (moved away, expanded, deleted) is not.
inline bool isInPlace(const MaterialItems& items, std::size_t i, const ShieldLayout& layout,
                      const Criteria& criteria) {
    if (!items.alive[i]) {
        return false;
    }
    const auto& body = layout.bodies[static_cast<std::size_t>(items.body[i])];
    if (items.density[i] < criteria.intactDensityRatio * body.referenceDensity) {
        return false;
    }
    const double window = axialWindow(body, criteria);
    if (items.hasReference) {
        return std::fabs(items.z[i] - items.z0[i]) <= window;
    }
    return items.z[i] >= body.zFront - window && items.z[i] <= body.zRear + window;
}

/// In place and not failed: plate material that still carries load.
inline bool isIntact(const MaterialItems& items, std::size_t i, const ShieldLayout& layout,
                     const Criteria& criteria) {
    return isInPlace(items, i, layout, criteria) && !isFailed(items, i, layout, criteria);
}

/// Whether items[i] belongs to body `b` (guards against out-of-range ids).
inline bool belongsTo(const MaterialItems& items, std::size_t i, std::size_t b) {
    return items.body[i] >= 0 && static_cast<std::size_t>(items.body[i]) == b;
}

/// Whether items[i] is body `b`'s own material in the material frame: for an FE body its
/// elements only. The particles its eroded elements became carry the element's reference
/// position but are debris now; counted as the body's material they would close the very hole
/// their elements left.
inline bool isBodyMaterial(const MaterialItems& items, std::size_t i, const ShieldLayout& layout,
                           std::size_t b) {
    return belongsTo(items, i, b) && (!layout.bodies[b].fe || items.isElement(i));
}

} // namespace hvi::assess
