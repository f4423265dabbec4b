// Input checks shared by the geometry reductions (FoamLayerStack, HoneycombRings).
//
// Every problem in one input block is collected before anything is thrown, so a user fixes
// them all in one pass (STYLE.md practice 5); the result is one hvi::InputError whose issues
// carry a JSON pointer made of the caller's prefix and the key, e.g. "/panel" + "/ppi".
// The keys are the snake_case JSON keys (with units) the tools are expected to use, so the
// message points at the right place in the user's file without translation.
#pragma once

#include "core/Error.hpp"

#include <limits>
#include <string>
#include <vector>

namespace hvi::geometry {

/// Marks a required input that was not given. NaN so that it can never be mistaken for a
/// value: every check rejects it with "missing or not a number".
inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

/// A number for messages: up to 6 significant digits ("0.0889", "50.8", "1e-09").
std::string formatNumber(double value);

/// Collects the problems of one input block; throws them all at once.
class InputChecks {
public:
    /// file: as the user named it; pointerPrefix: JSON pointer of the block ("" = document root).
    InputChecks(std::string file, std::string pointerPrefix);

    /// The JSON pointer of a key of the block: prefix + "/" + key.
    std::string pointer(const std::string& key) const;

    /// Records an issue unless value is finite. Returns whether the value passed.
    bool finite(const std::string& key, double value, const std::string& expected);
    /// Records an issue unless value is finite and > 0.
    bool positive(const std::string& key, double value, const std::string& expected);
    /// Records an issue unless value is finite and inside the interval; each end open or closed.
    bool inRange(const std::string& key, double value, double low, bool lowClosed, double high,
                 bool highClosed, const std::string& expected);
    /// Records an issue unless an optional input was left unset (it is ignored by the choice
    /// named in `why`, and silently ignoring a given value hides a user's mistake).
    void unused(const std::string& key, double value, const std::string& why);
    /// Records any other issue.
    void add(const std::string& key, const std::string& problem, const std::string& expected);

    bool empty() const { return m_issues.empty(); }
    /// Throws hvi::InputError carrying every recorded issue, if there is any.
    void throwIfAny() const;

private:
    std::string m_file;
    std::string m_prefix;
    std::vector<InputIssue> m_issues;
};

} // namespace hvi::geometry
