#include "assess/PenetrationDepth.hpp"

#include "assess/FailurePath.hpp"
#include "assess/MaterialState.hpp"

#include <algorithm>
#include <limits>

namespace hvi::assess {

std::optional<PenetrationDepth>
penetrationDepth(const MaterialItems& items, const ShieldLayout& layout, const Criteria& criteria) {
    std::vector<std::size_t> bodies = layout.core;
    if (layout.rearWall) {
        bodies.push_back(*layout.rearWall);
    }
    if (bodies.empty()) {
        return std::nullopt;
    }
    std::vector<char> considered(layout.bodies.size(), 0);
    for (auto b : bodies) {
        considered[b] = 1;
    }
    // Deepest failed point per body.
    const double none = -std::numeric_limits<double>::infinity();
    std::vector<double> deepest(layout.bodies.size(), none);
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items.body[i] < 0) {
            continue;
        }
        const auto b = static_cast<std::size_t>(items.body[i]);
        if (b >= considered.size() || !considered[b] || !isFailed(items, i, layout, criteria)) {
            continue;
        }
        const BodyLayout& body = layout.bodies[b];
        const double z = std::min(items.z0[i] + 0.5 * body.spacing, body.zRear);
        deepest[b] = std::max(deepest[b], z);
    }

    PenetrationDepth result;
    const double origin = layout.depthOriginZ();
    double deepestZ = none;
    for (auto b : bodies) {
        if (deepest[b] == none) {
            continue;
        }
        result.reachedBodies.push_back(b);
        if (deepest[b] > deepestZ) {
            deepestZ = deepest[b];
            result.deepestBody = b;
        }
    }
    if (result.deepestBody) {
        result.depthMm = std::max(0.0, deepestZ - origin);
    }
    for (auto b : layout.core) {
        if (deepest[b] != none && failurePath(items, b, layout, criteria).crosses) {
            result.perforatedLayers.push_back(b);
        }
    }
    return result;
}

} // namespace hvi::assess
