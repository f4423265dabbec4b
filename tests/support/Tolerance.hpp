// Tolerance-based comparison used by every golden and verification test:
// |a - b| <= atol + rtol * |b|, with b the reference value. On failure the message prints
// the quantity, both values and the difference, so a broken golden is diagnosable from
// the CTest log alone.
#pragma once

#include <cmath>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace hvi::test {

inline ::testing::AssertionResult near(const std::string& what, double actual, double reference,
                                       double atol, double rtol) {
    const double diff = std::fabs(actual - reference);
    const double allowed = atol + rtol * std::fabs(reference);
    if (std::isfinite(actual) && diff <= allowed) {
        return ::testing::AssertionSuccess();
    }
    std::ostringstream out;
    out.precision(10);
    out << what << ": got " << actual << ", reference " << reference << ", |a-b| = " << diff
        << " > allowed " << allowed << " (atol " << atol << ", rtol " << rtol << ")";
    return ::testing::AssertionFailure() << out.str();
}

} // namespace hvi::test
