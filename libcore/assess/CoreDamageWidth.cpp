#include "assess/CoreDamageWidth.hpp"

#include "assess/MaterialState.hpp"

#include <algorithm>
#include <vector>

namespace hvi::assess {

std::optional<double> coreDamageWidthMm(const MaterialItems& items, const ShieldLayout& layout,
                                        const Criteria& criteria) {
    if (layout.core.empty()) {
        return std::nullopt;
    }
    std::vector<char> isCore(layout.bodies.size(), 0);
    for (auto b : layout.core) {
        isCore[b] = 1;
    }
    double width = 0.0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items.body[i] < 0) {
            continue;
        }
        const auto b = static_cast<std::size_t>(items.body[i]);
        if (b < isCore.size() && isCore[b] && isFailed(items, i, layout, criteria)) {
            const BodyLayout& body = layout.bodies[b];
            const double r = std::min(items.r0[i] + 0.5 * body.spacing, body.rMax);
            width = std::max(width, 2.0 * r);
        }
    }
    return width;
}

} // namespace hvi::assess
