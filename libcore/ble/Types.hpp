// Types shared by every ballistic limit equation (BLE) in hvi::ble.
//
// Units inside hvi::ble are the NASA JSC system the equations were fitted in: lengths and
// diameters in cm, densities in g/cm^3, velocity in km/s, yield stress in ksi, projectile
// mass in g, areal density in g/cm^2; angles are in degrees at the API and measured from the
// surface normal. The equations are not dimensionally homogeneous (the 18/19 and 1/3
// exponents), so evaluating them in any other unit system gives wrong numbers, not just
// differently scaled ones. Convert at the file boundary (core/Units.hpp), never in here.
//
// Non-physical arguments (negative thickness, angle >= 90 deg, ...) throw
// std::invalid_argument naming the argument: the tool is expected to have rejected them
// against its schema first, so reaching the throw is a wiring error, not a user error.
#pragma once

#include <string>
#include <vector>

namespace hvi::ble {

/// The projectile: a sphere of given diameter and density, its speed and obliquity.
struct Threat {
    double diameterCm = 0.0;  ///< projectile diameter [cm]; <= 0 means "not known" in
                              ///< performance calls (warnings then use d_c instead)
    double densityGCm3 = 2.7; ///< projectile density [g/cm^3]
    double velocityKmS = 7.0; ///< impact speed [km/s]
    double angleDeg = 0.0;    ///< obliquity from the surface normal [deg], 0 <= angle < 90
};

/// Velocity regime of a three-part BLE. The boundaries depend on the shield type (Whipple:
/// normal velocity 3 and 7 km/s; foam: 2.25 and 4 km/s scaled by cos^(1/3); ...).
enum class Regime {
    Ballistic,     ///< low velocity: the projectile stays intact, penetration mechanics
    Shatter,       ///< intermediate: the projectile fragments; linear blend of the other two
    Hypervelocity, ///< melt/vaporisation: a debris cloud loads the rear wall impulsively
};

/// Stable lower-case name for output files ("ballistic", "shatter", "hypervelocity").
inline const char* regimeName(Regime regime) {
    switch (regime) {
    case Regime::Ballistic:
        return "ballistic";
    case Regime::Shatter:
        return "shatter";
    case Regime::Hypervelocity:
        return "hypervelocity";
    }
    return "unknown";
}

/// An input outside the range an equation was validated on, or an assumption the result
/// rests on. Codes are stable snake_case identifiers meant for output files and tests:
///   design_below_7km_s, design_below_hypervelocity_regime, thesis_inverted_yield_ratio,
///   standoff_over_diameter_below_15, bumper_ratio_below_0_18, angle_above_65deg,
///   angle_outside_validated_range, velocity_outside_validated_range,
///   diameter_outside_validated_range, foam_ble_ambiguity, foam_ppi_not_tested,
///   stuffing_fraction_outside_calibrated_range.
struct ValidityWarning {
    std::string code;
    std::string message;
};

/// What every performance (critical diameter) call returns.
struct CriticalDiameterResult {
    double criticalDiameterCm = 0.0; ///< largest projectile the shield stops [cm]
    Regime regime = Regime::Hypervelocity;
    std::vector<ValidityWarning> warnings;
};

/// True when `warnings` holds an entry with this code (for tools and tests).
inline bool hasWarning(const std::vector<ValidityWarning>& warnings, const std::string& code) {
    for (const auto& w : warnings) {
        if (w.code == code) {
            return true;
        }
    }
    return false;
}

} // namespace hvi::ble
