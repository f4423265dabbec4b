#include "geometry/InputChecks.hpp"

#include <cmath>
#include <sstream>

namespace hvi::geometry {

std::string formatNumber(double value) {
    std::ostringstream out;
    out.precision(6);
    out << value;
    return out.str();
}

InputChecks::InputChecks(std::string file, std::string pointerPrefix)
    : m_file(std::move(file)), m_prefix(std::move(pointerPrefix)) {}

std::string InputChecks::pointer(const std::string& key) const {
    return m_prefix + "/" + key;
}

void InputChecks::add(const std::string& key, const std::string& problem,
                      const std::string& expected) {
    m_issues.push_back({m_file, pointer(key), problem, expected});
}

bool InputChecks::finite(const std::string& key, double value, const std::string& expected) {
    if (std::isfinite(value)) {
        return true;
    }
    add(key,
        std::isnan(value) ? "missing or not a number"
                          : "must be finite, got " + formatNumber(value),
        expected);
    return false;
}

bool InputChecks::positive(const std::string& key, double value, const std::string& expected) {
    if (!finite(key, value, expected)) {
        return false;
    }
    if (value > 0.0) {
        return true;
    }
    add(key, "must be > 0, got " + formatNumber(value), expected);
    return false;
}

bool InputChecks::inRange(const std::string& key, double value, double low, bool lowClosed,
                          double high, bool highClosed, const std::string& expected) {
    if (!finite(key, value, expected)) {
        return false;
    }
    const bool aboveLow = lowClosed ? value >= low : value > low;
    const bool belowHigh = highClosed ? value <= high : value < high;
    if (aboveLow && belowHigh) {
        return true;
    }
    add(key,
        "must be in " + std::string(lowClosed ? "[" : "(") + formatNumber(low) + ", " +
            formatNumber(high) + (highClosed ? "]" : ")") + ", got " + formatNumber(value),
        expected);
    return false;
}

void InputChecks::unused(const std::string& key, double value, const std::string& why) {
    if (!std::isnan(value)) {
        add(key, "given (" + formatNumber(value) + ") but not used", why);
    }
}

void InputChecks::throwIfAny() const {
    if (!m_issues.empty()) {
        throw InputError(m_issues);
    }
}

} // namespace hvi::geometry
