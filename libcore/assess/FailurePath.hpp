// Through-thickness failure: is there a connected path of failed (or deleted, eroded)
// material of one body from one face to the other?
//
// The test runs in the material (reference) frame: items are placed at their positions in
// the first snapshot, so a plate that has bulged, thinned or been pushed is judged on its
// original lattice, and "connected" means neighbours in the material as it was made. Two
// failed items are connected when their reference distance is at most linkSpacings (1.5)
// particle spacings, which links the 8 lattice neighbours. The faces are the first and last
// spacing of the body across its thin direction: z for plates and layers, r for honeycomb
// ring walls (bodies thinner in r than in z). A path exists when one connected set of failed
// items touches both faces.
//
// Without reference positions (MaterialItems::hasReference false) current positions are used.
#pragma once

#include "assess/Criteria.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/ShieldLayout.hpp"

#include <cstddef>

namespace hvi::assess {

struct FailurePath {
    bool crosses = false;        ///< a connected set of failed items touches both faces
    std::size_t failedItems = 0; ///< failed items of the body
    double pathRadiusMm = 0.0;   ///< smallest reference r of the crossing sets (plates)
};

FailurePath failurePath(const MaterialItems& items, std::size_t body, const ShieldLayout& layout,
                        const Criteria& criteria);

} // namespace hvi::assess
