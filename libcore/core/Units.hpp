// Unit conversions used at the boundaries of the toolkit.
//
// Files carry their units in their keys (diameter_mm, velocity_km_s, yield_MPa). Inside,
// the ballistic-limit equations work in the NASA JSC system (cm, g/cm^3, km/s, ksi; the
// equations are not dimensionally homogeneous, so this is not a free choice), and the
// hydrocode works in mm, microseconds and mg, where velocity is km/s, density g/cm^3,
// pressure GPa, specific energy MJ/kg and energy J (see docs/conventions.md).
#pragma once

namespace hvi::units {

inline constexpr double kMmPerCm = 10.0;
inline constexpr double kMmPerInch = 25.4;
/// 1 ksi = 6.894757293 MPa (exact from 1 lbf/in^2 = 6894.757293168 Pa).
inline constexpr double kMpaPerKsi = 6.894757293168;
inline constexpr double kGpaPerMpa = 1.0e-3;
inline constexpr double kPi = 3.14159265358979323846;

constexpr double mmToCm(double mm) { return mm / kMmPerCm; }
constexpr double cmToMm(double cm) { return cm * kMmPerCm; }
constexpr double mmToInch(double mm) { return mm / kMmPerInch; }
constexpr double inchToMm(double inch) { return inch * kMmPerInch; }
constexpr double mpaToKsi(double mpa) { return mpa / kMpaPerKsi; }
constexpr double ksiToMpa(double ksi) { return ksi * kMpaPerKsi; }
constexpr double degToRad(double deg) { return deg * kPi / 180.0; }

// Hydrocode boundary conversions (mm, us, mg system: see docs/conventions.md).
/// A rate given per second, expressed per microsecond (the hydrocode's time unit).
constexpr double perSecondToPerMicrosecond(double perSecond) { return perSecond * 1.0e-6; }
/// Specific heat J/(kg K) -> MJ/(kg K), since specific energy in the hydrocode is MJ/kg.
constexpr double jPerKgKToMjPerKgK(double jPerKgK) { return jPerKgK * 1.0e-6; }
/// MPa -> GPa (the hydrocode's stress unit).
constexpr double mpaToGpa(double mpa) { return mpa * kGpaPerMpa; }

} // namespace hvi::units
