// Guards shared by the BLE functions: reject non-physical arguments with a message that
// names the argument and its unit. Internal to hvi::ble (the tool validates input against
// its schema first; see Types.hpp for the policy).
#pragma once

#include "core/Units.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hvi::ble::detail {

/// Throws std::invalid_argument unless value > 0 and finite.
inline void requirePositive(const char* name, double value) {
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw std::invalid_argument(std::string("hvi::ble: ") + name + " must be > 0 (got " +
                                    std::to_string(value) + ")");
    }
}

/// Throws std::invalid_argument unless value >= 0 and finite.
inline void requireNonNegative(const char* name, double value) {
    if (!(value >= 0.0) || !std::isfinite(value)) {
        throw std::invalid_argument(std::string("hvi::ble: ") + name + " must be >= 0 (got " +
                                    std::to_string(value) + ")");
    }
}

/// Obliquity from the normal: 0 <= angle < 90 deg. At 90 deg cos = 0 and every BLE divides
/// by a power of it; a grazing impact is not something these equations describe.
inline void requireAngle(double angleDeg) {
    if (!(angleDeg >= 0.0) || !(angleDeg < 90.0)) {
        throw std::invalid_argument("hvi::ble: angle must be in [0, 90) deg (got " +
                                    std::to_string(angleDeg) + ")");
    }
}

inline double cosDeg(double angleDeg) {
    return std::cos(units::degToRad(angleDeg));
}

} // namespace hvi::ble::detail
