// Core damage width in one snapshot (docs/metrics.md, "Core damage width"): the diameter of
// the region of the core (core layers and honeycomb rings) holding failed or eroded material,
// 2 * (largest reference radius of a failed core item + half a spacing). The source study
// reports it for honeycomb panels (30.5 mm for HITF04150). Reference radii make it a
// property of the panel, not of where failed material was pushed to.
#pragma once

#include "assess/Criteria.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/ShieldLayout.hpp"

#include <optional>

namespace hvi::assess {

/// Nullopt when the scene has no core bodies; 0 when no core material failed.
std::optional<double> coreDamageWidthMm(const MaterialItems& items, const ShieldLayout& layout,
                                        const Criteria& criteria);

} // namespace hvi::assess
