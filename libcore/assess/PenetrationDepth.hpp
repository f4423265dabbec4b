// Penetration depth into the core in one snapshot (docs/metrics.md, "Penetration depth").
//
// Measured along z from the bumper's rear face (ShieldLayout::depthOriginZ). The bodies that
// can be "reached" are the core layers, the honeycomb rings and the rear wall. A body is
// reached when it holds failed or eroded material (MaterialState.hpp); the depth is that of
// the deepest failed item over all reached bodies, at its reference (initial) position plus
// half a spacing (the far side of the item), clipped to its body's rear face. Using the
// reference position makes the depth a property of the panel, not of where failed material
// has been pushed to. 0 when no core body or rear wall holds failed material.
//
// Also reported: which body is the deepest reached, how many core bodies were reached, and
// how many core layers (plates) have a through-thickness failure path (FailurePath.hpp).
// The deepest debris position is a debris-cloud quantity (DebrisCloud.hpp).
#pragma once

#include "assess/Criteria.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/ShieldLayout.hpp"

#include <optional>
#include <vector>

namespace hvi::assess {

struct PenetrationDepth {
    double depthMm = 0.0;
    std::optional<std::size_t> deepestBody;    ///< body index
    std::vector<std::size_t> reachedBodies;    ///< core bodies and rear wall with failed items
    std::vector<std::size_t> perforatedLayers; ///< core bodies with a through-thickness path
};

/// Nullopt when the scene has neither core bodies nor a rear wall.
std::optional<PenetrationDepth>
penetrationDepth(const MaterialItems& items, const ShieldLayout& layout, const Criteria& criteria);

} // namespace hvi::assess
