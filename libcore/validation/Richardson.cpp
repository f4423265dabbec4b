#include "validation/Richardson.hpp"

#include "ble/RootFinding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace hvi::validation {

Extrapolation richardson(std::vector<double> spacings, std::vector<double> values) {
    if (spacings.size() != values.size()) {
        throw std::invalid_argument("richardson: as many values as spacings");
    }
    std::vector<std::size_t> idx(spacings.size());
    std::iota(idx.begin(), idx.end(), 0);
    std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return spacings[a] > spacings[b]; });
    Extrapolation e;
    if (idx.size() < 3) {
        e.reason = "fewer than three spacings";
        return e;
    }
    const std::size_t n = idx.size();
    const double h1 = spacings[idx[n - 3]], h2 = spacings[idx[n - 2]], h3 = spacings[idx[n - 1]];
    const double f1 = values[idx[n - 3]], f2 = values[idx[n - 2]], f3 = values[idx[n - 1]];
    if (!(h1 > h2 && h2 > h3 && h3 > 0.0)) {
        e.reason = "the three finest spacings are not distinct and positive";
        return e;
    }
    const double d12 = f1 - f2, d23 = f2 - f3;
    if (d23 == 0.0 && d12 == 0.0) {
        e.ok = true; // converged to the last digit: no order to observe
        e.order = std::numeric_limits<double>::infinity();
        e.limit = f3;
        return e;
    }
    const double ratio = d12 / d23;
    if (!(ratio > 0.0) || !std::isfinite(ratio)) {
        e.reason = "the differences change sign (oscillating: not in the asymptotic range)";
        return e;
    }
    // The model's ratio grows with p (for uneven ratios it can be below 1 at small p).
    auto modelRatio = [&](double p) {
        return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p));
    };
    auto g = [&](double p) { return std::log(ratio) - std::log(modelRatio(p)); };
    const auto root = ble::brentRoot(g, kMinOrder, kMaxOrder, 1e-10);
    if (!root.bracketed) {
        e.reason = ratio < modelRatio(kMinOrder)
                       ? "the differences do not shrink (observed order below 0.1)"
                       : "the observed order is above 8";
        return e;
    }
    const double p = root.x;
    e.ok = true;
    e.order = p;
    e.limit = f3 - d23 * std::pow(h3, p) / (std::pow(h2, p) - std::pow(h3, p));
    return e;
}

} // namespace hvi::validation
