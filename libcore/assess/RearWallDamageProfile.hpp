// The rear wall's damage profile in one snapshot: per radial bin of the wall's initial extent
// (one spacing wide, by the items' reference radius), the failed fraction of the bin's mass
// (failed, eroded or deleted: through how much of the thickness the wall has failed there)
// and the mass-weighted mean damage D. A designer reads from it how wide the damaged zone is
// and how close it came to a through-thickness failure.
#pragma once

#include "assess/Criteria.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/ShieldLayout.hpp"

#include <optional>
#include <vector>

namespace hvi::assess {

struct RearWallDamageProfile {
    double timeUs = 0.0;
    std::vector<double> radiusMm;       ///< bin centres
    std::vector<double> failedFraction; ///< [-], 0..1
    std::vector<double> meanDamage;     ///< [-], 0..1 (deleted items count as D = 1)
};

/// Nullopt without a rear wall.
std::optional<RearWallDamageProfile> rearWallDamageProfile(const MaterialItems& items,
                                                           const ShieldLayout& layout,
                                                           const Criteria& criteria);

} // namespace hvi::assess
