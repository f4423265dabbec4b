// Rear-wall perforation in one snapshot: the P/NP verdict (docs/metrics.md, "Rear wall
// perforated").
//
// The rear wall is perforated when either
//  (a) through-thickness failure: a connected path of failed or eroded rear-wall material
//      crosses its thickness (FailurePath.hpp, in the material frame), or
//  (b) material crossed: at least minCrossingItems (3) alive items of bodies in front of the
//      rear wall (projectile, bumper, core) are beyond the wall's *current* rear surface by
//      more than one particle spacing and moving outward (Vz > 0). The rear surface is taken
//      per radial bin (one spacing wide) as the top of the wall material still in place
//      there: from the rearmost wall item that has not failed (or, where all have, the wall
//      item nearest the wall's mid-plane) up through contiguous wall items, failed or not, no
//      more than 1.5 spacings apart. So a bulging wall with debris in its dent is not
//      perforated, failed wall material still in place still holds debris back, and a bin
//      with no wall material left uses the wall's initial rear face.
// Informational only (not part of the verdict):
//  * detached spall, i.e. rear-wall material beyond that surface by more than two spacings,
//    moving outward;
//  * the open columns: radial bins (one spacing wide, by reference radius) in which every
//    wall item across the thickness has failed, a hole through the wall in the material frame;
//  * the perforation's outer radius: the outer edge of the outermost open column, of the
//    innermost point of a crossing failure path (a crack that leaves no column open), or of
//    the outermost crossing item, whichever is largest; and whether it lies within
//    Criteria::axisBandSpacings of the axis (axisymmetric runs). In two-dimensional
//    axisymmetry material on the axis cannot move off it, so a perforation confined to the
//    first columns there is a verdict to read with care (docs/metrics.md).
#pragma once

#include "assess/Criteria.hpp"
#include "assess/MaterialItems.hpp"
#include "assess/ShieldLayout.hpp"

#include <optional>

namespace hvi::assess {

struct RearWallPerforation {
    bool perforated = false;
    bool throughThicknessFailure = false; ///< criterion (a)
    bool materialCrossed = false;         ///< criterion (b)
    std::size_t crossingItems = 0;
    double crossingMassMg = 0.0;
    std::size_t failedItems = 0;
    bool detachedSpall = false;
    std::size_t openColumns = 0;      ///< columns failed through the whole thickness
    double openRadiusMm = 0.0;        ///< outer edge of the outermost open column (0: none)
    double perforationRadiusMm = 0.0; ///< outer radius of the perforation (0: not perforated)
    bool axisConfined = false;        ///< perforated, all within the axis band (axisymmetric)
};

/// Nullopt when the scene has no rear_wall body.
std::optional<RearWallPerforation> rearWallPerforation(const MaterialItems& items,
                                                       const ShieldLayout& layout,
                                                       const Criteria& criteria);

} // namespace hvi::assess
