// Bracketed scalar root finding (Brent's method: inverse quadratic interpolation and secant
// steps, falling back to bisection, so it keeps bisection's guarantee on a sign-changing
// bracket and converges superlinearly on smooth functions).
//
// Source: R.P. Brent, "Algorithms for Minimization without Derivatives" (1973), ch. 4; the
// "zeroin" formulation of Forsythe, Malcolm and Moler, "Computer Methods for Mathematical
// Computations" (1977). Written here from the algorithm description.
#pragma once

#include <functional>

namespace hvi::ble {

struct RootResult {
    bool bracketed = false; ///< f(lo) and f(hi) had opposite signs (or one was zero)
    bool converged = false; ///< the bracket shrank below the tolerance within maxIterations
    double x = 0.0;         ///< the root (valid when bracketed)
    double fx = 0.0;        ///< f(x)
    int iterations = 0;     ///< function evaluations after the two end points
};

/// Root of f in [lo, hi] to an absolute tolerance xTol on x. Returns bracketed = false
/// (and does not iterate) when f(lo) and f(hi) have the same sign.
RootResult brentRoot(const std::function<double(double)>& f, double lo, double hi,
                     double xTol = 1e-12, int maxIterations = 200);

} // namespace hvi::ble
