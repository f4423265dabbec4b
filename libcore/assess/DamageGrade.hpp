// The rear wall's damage graded as the hypervelocity-impact tests grade it, and the verdict
// that follows (docs/metrics.md, "Damage grade and verdict").
//
// NASA JSC (NASA/TM-2009-214785, sec. 4.2, fig. 4-4) and Christiansen & Kerr (IJIE 26, 2001)
// count a Whipple shot as failed when the rear wall is perforated or sheds detached spall from
// its back face; Ryan, Ordonez, Christiansen and Lear's foam-core panel tests (Proc. 11th
// Hypervelocity Impact Symposium, 2010) count the onset of material ejection from the rear
// facesheet, however small. A bulge or attached spall passes. The grades, worst last:
//   none              nothing below;
//   crater            failed or eroded material in the wall's front half, or its front dented;
//   bulge             the back face bulged, or failed material under it that stayed attached
//                     (attached spall);
//   detached_spall    wall material ejected from the back face (RearWallPerforation.hpp);
//   perforation       a through-thickness failure path, or material of the bodies in front
//                     of the wall beyond its rear surface.
// The verdict is P when the grade is detached_spall or perforation.
// Units: none (grades); the thresholds behind them are in Criteria.hpp (mm, km/s).
#pragma once

#include "assess/Criteria.hpp"
#include "assess/RearWallPerforation.hpp"

#include <string_view>

namespace hvi::assess {

enum class DamageGrade { None = 0, Crater, Bulge, DetachedSpall, Perforation };

/// "none", "crater", "bulge_or_attached_spall", "detached_spall", "perforation".
std::string_view toString(DamageGrade grade);

/// The grade of one snapshot's rear wall.
DamageGrade damageGrade(const RearWallPerforation& wall, double spacingMm,
                        const Criteria& criteria);

/// Whether a grade fails the shield as the tests define failure.
inline bool isFailure(DamageGrade grade) {
    return grade >= DamageGrade::DetachedSpall;
}

} // namespace hvi::assess
