// Brent's root finder; see RootFinding.hpp.
#include "ble/RootFinding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hvi::ble {

RootResult brentRoot(const std::function<double(double)>& f, double lo, double hi, double xTol,
                     int maxIterations) {
    RootResult result;
    double a = lo;
    double b = hi;
    double fa = f(a);
    double fb = f(b);
    if (fa == 0.0 || fb == 0.0) {
        result.bracketed = result.converged = true;
        result.x = fa == 0.0 ? a : b;
        result.fx = 0.0;
        return result;
    }
    if ((fa > 0.0) == (fb > 0.0)) {
        return result;
    }
    result.bracketed = true;

    // b is the best estimate, c the point that keeps the sign change with b, a the previous b.
    double c = a;
    double fc = fa;
    double d = b - a; // last step
    double e = d;     // step before last
    const double eps = std::numeric_limits<double>::epsilon();
    for (int it = 0; it < maxIterations; ++it) {
        if ((fb > 0.0) == (fc > 0.0)) {
            c = a;
            fc = fa;
            d = e = b - a;
        }
        if (std::fabs(fc) < std::fabs(fb)) {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        const double tol = 2.0 * eps * std::fabs(b) + 0.5 * xTol;
        const double m = 0.5 * (c - b);
        if (std::fabs(m) <= tol || fb == 0.0) {
            result.converged = true;
            break;
        }
        if (std::fabs(e) < tol || std::fabs(fa) <= std::fabs(fb)) {
            d = e = m; // bisection: the last interpolation step did not shrink enough
        } else {
            const double s = fb / fa;
            double p = 0.0;
            double q = 0.0;
            if (a == c) { // secant
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else { // inverse quadratic interpolation through a, b, c
                const double qa = fa / fc;
                const double r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if (p > 0.0) {
                q = -q;
            } else {
                p = -p;
            }
            // Accept the interpolated step only if it stays well inside the bracket and
            // shrinks faster than bisection would.
            if (2.0 * p < std::min(3.0 * m * q - std::fabs(tol * q), std::fabs(e * q))) {
                e = d;
                d = p / q;
            } else {
                d = e = m;
            }
        }
        a = b;
        fa = fb;
        b += std::fabs(d) > tol ? d : (m > 0.0 ? tol : -tol);
        fb = f(b);
        result.iterations = it + 1;
    }
    result.x = b;
    result.fx = fb;
    return result;
}

} // namespace hvi::ble
