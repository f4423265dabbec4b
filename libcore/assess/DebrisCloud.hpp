// The debris cloud in one snapshot (docs/metrics.md, "Debris cloud").
//
// Debris is the alive material that has gone through the bumper: projectile and bumper items
// beyond the bumper's rear face by more than the bumper's axial window (one plate thickness,
// at least two spacings), and failed items of the core and rear wall that have moved
// downstream by more than two of their spacings. Without a bumper, projectile items beyond the
// front face of the first target body.
//
// Positions are quantiles of mass, so one stray particle ahead of the cloud does not define
// it: the leading edge is the z with a fraction 1e-3 of the debris mass ahead of it; the
// leading-edge speed is the mass-weighted axial velocity of the debris from the leading edge
// back to the 1 % mass quantile (the front slab, without the stragglers ahead of the edge);
// the cloud radius is the r with 1e-3 of the mass outside it. Also the centre of mass and
// its axial speed, and the fastest axial speed of any debris item.
#pragma once

#include "assess/Criteria.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/ShieldLayout.hpp"

#include <cstddef>

namespace hvi::assess {

struct DebrisCloud {
    double timeUs = 0.0;
    std::size_t items = 0;
    double massMg = 0.0;
    double leadingEdgeZMm = 0.0;
    double leadingEdgeDepthMm = 0.0; ///< leading edge - ShieldLayout::depthOriginZ()
    double leadingEdgeSpeedKmS = 0.0;
    double maxAxialSpeedKmS = 0.0;
    double radiusMm = 0.0;
    double centreOfMassZMm = 0.0;
    double centreOfMassSpeedKmS = 0.0;
};

/// items == 0 when there is no debris (yet).
DebrisCloud debrisCloud(const MaterialItems& items, const ShieldLayout& layout,
                        const Criteria& criteria);

} // namespace hvi::assess
