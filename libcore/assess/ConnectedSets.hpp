// Connected sets of points in the (z, r) plane: two points are linked when they are at most
// `link` apart (or `strongLink` when both are marked strong: sound material that stays whole
// when stretched), and a set is everything reachable through such links (union-find over a
// grid of cells the larger distance wide, so each point meets the points of 9 cells only).
//
// Used for material that holds together: failed items forming a path through a plate
// (FailurePath.hpp) and the part of a rear wall still joined to the wall (RearWallPerforation).
// Units: whatever the coordinates carry (mm in assess).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hvi::assess {

/// One label per point: labels[i] == labels[j] exactly when i and j are in the same set.
/// Labels are point indices (the set's representative), so they lie in [0, z.size()).
/// `link` must be positive; z and r must be the same length. With `strong` (empty, or one
/// flag per point), a pair of strong points is linked up to max(link, strongLink).
std::vector<std::size_t> connectedSets(const std::vector<double>& z, const std::vector<double>& r,
                                       double link, const std::vector<std::uint8_t>& strong = {},
                                       double strongLink = 0.0);

} // namespace hvi::assess
