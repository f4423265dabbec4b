#include "assess/FailurePath.hpp"

#include "assess/ConnectedSets.hpp"
#include "assess/MaterialState.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace hvi::assess {

FailurePath failurePath(const MaterialItems& items, std::size_t b, const ShieldLayout& layout,
                        const Criteria& criteria) {
    const BodyLayout& body = layout.bodies[b];
    const bool acrossR = body.thinInR();
    const double lo = acrossR ? body.rMin : body.zFront;
    const double hi = acrossR ? body.rMax : body.zRear;
    const double s = body.spacing;
    const double link = criteria.linkSpacings * s;

    // Failed items of the body, at their reference positions.
    std::vector<double> pz, pr;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (belongsTo(items, i, b) && isFailed(items, i, layout, criteria)) {
            pz.push_back(items.z0[i]);
            pr.push_back(items.r0[i]);
        }
    }
    FailurePath result;
    result.failedItems = pz.size();
    if (pz.empty()) {
        return result;
    }
    const std::size_t n = pz.size();
    const std::vector<std::size_t> label = connectedSets(pz, pr, link);
    // Roots touching each face.
    std::unordered_map<std::size_t, std::uint8_t> faces; // bit 1 front, bit 2 rear
    std::unordered_map<std::size_t, double> minR;
    for (std::size_t k = 0; k < n; ++k) {
        const double u = acrossR ? pr[k] : pz[k];
        const std::size_t root = label[k];
        auto& f = faces[root];
        if (u <= lo + s) {
            f |= 1;
        }
        if (u >= hi - s) {
            f |= 2;
        }
        auto [it, inserted] = minR.emplace(root, pr[k]);
        if (!inserted) {
            it->second = std::min(it->second, pr[k]);
        }
    }
    double pathR = std::numeric_limits<double>::infinity();
    for (const auto& [root, f] : faces) {
        if (f == 3) {
            result.crosses = true;
            pathR = std::min(pathR, minR[root]);
        }
    }
    if (result.crosses) {
        result.pathRadiusMm = pathR;
    }
    return result;
}

} // namespace hvi::assess
