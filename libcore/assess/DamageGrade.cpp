#include "assess/DamageGrade.hpp"

namespace hvi::assess {

std::string_view toString(DamageGrade grade) {
    switch (grade) {
    case DamageGrade::None:
        return "none";
    case DamageGrade::Crater:
        return "crater";
    case DamageGrade::Bulge:
        return "bulge_or_attached_spall";
    case DamageGrade::DetachedSpall:
        return "detached_spall";
    case DamageGrade::Perforation:
        return "perforation";
    }
    return "none";
}

DamageGrade damageGrade(const RearWallPerforation& wall, double spacingMm,
                        const Criteria& criteria) {
    if (wall.perforated) {
        return DamageGrade::Perforation;
    }
    if (wall.detachedSpall) {
        return DamageGrade::DetachedSpall;
    }
    const double moved = criteria.bulgeSpacings * spacingMm;
    if (wall.bulgeMm >= moved || wall.failedRearHalf) {
        return DamageGrade::Bulge;
    }
    if (wall.dentMm >= moved || wall.failedFrontHalf) {
        return DamageGrade::Crater;
    }
    return DamageGrade::None;
}

} // namespace hvi::assess
