// Rear-wall perforation in one snapshot: the P/NP verdict (docs/metrics.md, "Rear wall
// perforated").
//
// The rear wall is perforated when either
//  (a) through-thickness failure: a connected path of failed or eroded rear-wall material
//      crosses its thickness (FailurePath.hpp, in the material frame), or
//  (b) material crossed: at least minCrossingItems (3) alive items of bodies in front of the
//      rear wall (projectile, bumper, core) are beyond the wall's *current* rear surface by
//      more than one particle spacing and moving outward (Vz > 0). The rear surface is taken
//      per radial bin (one spacing wide) as the rearmost item there of the wall as it
//      stands: the set of the wall's alive items (sound, failed in place, or eroded-element
//      particles still touching it) joined at their current positions within
//      Criteria::joinSpacings that holds most of the wall's own material (ConnectedSets.hpp).
//      So a bulging wall with debris in its dent is not perforated, failed wall material
//      still in place still holds debris back, a scab that has left the wall is not its
//      surface however sound it is, and a bin with no wall material left uses the wall's
//      initial rear face.
// The damage short of perforation, graded as the tests grade it (DamageGrade.hpp):
//  * detached spall: at least minCrossingItems items of the rear wall's own body beyond that
//    surface by more than two spacings and moving outward (vz > 0): material that has left
//    the wall's back face, a whole scab included. The particles of eroded wall elements count (an
//    eroded element behind the back face, flying away, is wall material ejected from it); material
//    of the wall thrown back off its front face does not (it is in front of the surface, vz < 0);
//  * bulge: the wall's rear row has moved outward by at least one spacing more than the
//    outer quarter of that row (the whole wall drifting with the momentum it took, free at
//    its edge, is no bulge); bulgeMm is the largest such displacement. The wall here is its
//    own dense, unfailed material wherever it has moved, short of spall (more than two
//    spacings behind the rear surface) and of ejecta (more than its axial window in front of
//    its initial front face);
//  * attached spall: failed wall material of the rear half still part of the wall (a cavity
//    or crack under the back face) without a path through the thickness;
//  * crater: failed or eroded wall material in its front half, or its front row dented by at
//    least one spacing (relative to that row's outer quarter, as the bulge).
// The state at the run's end (is it at rest?): the fastest axial speed of the wall's
// unfailed material (as above), and the items of other bodies in front of the wall's rear
// surface that still move toward it faster than Criteria::restSpeedKmS.
// spallRadiusMm is where the spall came from (initial radius, the material frame).
// Units: mm, km/s, mg.
// Informational only (not part of the verdict):
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
    bool detachedSpall = false; ///< at least minCrossingItems spall items
    std::size_t spallItems = 0; ///< wall items detached behind its surface
    double spallMassMg = 0.0;
    double spallRadiusMm = 0.0;          ///< outermost spall item's initial r + half a spacing
    double bulgeMm = 0.0;                ///< largest outward move of the rear row (drift removed)
    double dentMm = 0.0;                 ///< largest +z move of the front row (drift removed)
    bool failedFrontHalf = false;        ///< failed or eroded wall material in its front half
    bool failedRearHalf = false;         ///< failed wall material in place in its rear half
    double wallMaxSpeedKmS = 0.0;        ///< fastest |vz| of the wall's unfailed material
    std::size_t approachingItems = 0;    ///< other items in front of it moving toward it
    double approachingMaxSpeedKmS = 0.0; ///< their fastest vz
    std::size_t openColumns = 0;         ///< columns failed through the whole thickness
    double openRadiusMm = 0.0;           ///< outer edge of the outermost open column (0: none)
    double perforationRadiusMm = 0.0;    ///< outer radius of the perforation (0: not perforated)
    bool axisConfined = false;           ///< perforated, all within the axis band (axisymmetric)
    bool spallAxisConfined = false;      ///< detached spall, all within the axis band
};

/// The width of the wall's axis band [mm]: Criteria::axisBandSpacings of its columns (one
/// spacing wide, or a little more or less where its width is not a whole number of spacings);
/// negative for a planar run or a wall that does not reach the axis.
double axisBandMm(const ShieldLayout& layout, std::size_t wall, const Criteria& criteria);

/// Nullopt when the scene has no rear_wall body.
std::optional<RearWallPerforation> rearWallPerforation(const MaterialItems& items,
                                                       const ShieldLayout& layout,
                                                       const Criteria& criteria);

} // namespace hvi::assess
