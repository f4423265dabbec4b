// The observed order of convergence and the Richardson estimate of the converged value of a
// metric computed at several particle spacings (issue #22, item 2).
//
// Model: f(h) = f0 + C h^p over the three finest spacings h1 > h2 > h3. The ratio
//   (f1 - f2) / (f2 - f3) = (h1^p - h2^p) / (h2^p - h3^p)
// fixes p (for a constant refinement ratio q it is q^p, Roache's form; here the ratios may
// differ, so p is found with Brent's method), and then
//   f0 = f3 - (f2 - f3) h3^p / (h2^p - h3^p).
// Source: L.F. Richardson, Phil. Trans. R. Soc. A 210 (1911) 307-357; P.J. Roache, "Verification
// and Validation in Computational Science and Engineering" (1998), ch. 5 (observed order from
// three grids, the grid convergence index). Written here from those descriptions.
//
// No estimate when the three differences do not shrink monotonically (oscillating or
// diverging: the ladder is not in the asymptotic range) or the order falls outside
// [kMinOrder, kMaxOrder]; the reason says which.
#pragma once

#include <string>
#include <vector>

namespace hvi::validation {

constexpr double kMinOrder = 0.1, kMaxOrder = 8.0;

struct Extrapolation {
    bool ok = false;
    double order = 0.0; ///< observed order p (infinite: the same value at all three)
    double limit = 0.0; ///< f0, the estimate at zero spacing
    std::string reason; ///< why there is no estimate (empty when ok)
};

/// From the metric's values at the spacings (any order, at least three distinct spacings; the
/// three finest are used).
Extrapolation richardson(std::vector<double> spacings, std::vector<double> values);

} // namespace hvi::validation
