// 2D SPH smoothing kernels with compact support 2h.
//
// References:
// * Cubic B-spline: J.J. Monaghan and J.C. Lattanzio, A&A 149 (1985) 135-143; J.J. Monaghan,
//   "Smoothed particle hydrodynamics", Annu. Rev. Astron. Astrophys. 30 (1992) 543-574.
//   W = sigma/h^2 * {1 - 3/2 q^2 + 3/4 q^3 (q < 1);  1/4 (2 - q)^3 (1 <= q < 2);  0},
//   sigma = 10/(7 pi) in 2D. (The source study's eq. 12 uses this kernel.)
// * Wendland C2 and C4: H. Wendland, Adv. Comput. Math. 4 (1995) 389-396; the 2D
//   normalisations are those of W. Dehnen and H. Aly, MNRAS 425 (2012) 1068-1082, Table 1,
//   rewritten for support radius H = 2h (s = q/2):
//   C2: W = 7/(4 pi h^2) (1 - q/2)^4 (1 + 2q)
//   C4: W = 9/(4 pi h^2) (1 - q/2)^6 (1 + 3q + 35/12 q^2)
//   Wendland kernels do not suffer the pairing instability and, per Spheral PR #497 (notes
//   section 0), C4 with ~6 points per kernel radius is the most stable choice near the axis.
//
// q = |x_i - x_j| / h. Each kernel gives, all for one h:
//   value(q, h)        W [1/mm^2]
//   dWdr(q, h)         dW/dr = (1/h) dW/dq [1/mm^3]; grad_i W_ij = dWdr * (x_i - x_j) / r
//   gradOverR(q, h)    (1/r) dW/dr [1/mm^4], finite at r = 0, so grad W = gradOverR * x_ij
//                      needs no division by a possibly zero distance
//   dWdh(q, h)         dW/dh at fixed r = -sigma (2 f + q f') / h^3 [1/mm^3], for grad-h
//                      terms (W = sigma f(q) / h^2)
// The normalisation makes the 2D integral of W equal 1. Axisymmetry is the solver's business
// (it divides masses by 2 pi r); these are plain 2D kernels.
//
// Selection: a runtime KernelType picks the kernel once; withKernel() hands the concrete
// struct to a generic lambda, so the loop inside is compiled per kernel, with no branch or
// virtual call per neighbour pair.
#pragma once

#include "core/Lanes.hpp"
#include "core/Units.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

namespace hvi::sph {

enum class KernelType { CubicSpline, WendlandC2, WendlandC4 };

/// Support radius in units of h, the same for every kernel here.
inline constexpr double kKernelSupport = 2.0;

struct CubicSplineKernel {
    static constexpr std::string_view kId = "kernel.cubic_spline";
    static constexpr double kNorm = 10.0 / (7.0 * units::kPi); ///< sigma (2D)

    /// Shape f(q): W = kNorm f(q) / h^2.
    static double shape(double q) noexcept {
        if (q < 1.0) {
            return 1.0 - 1.5 * q * q + 0.75 * q * q * q;
        }
        if (q < 2.0) {
            const double t = 2.0 - q;
            return 0.25 * t * t * t;
        }
        return 0.0;
    }
    /// f'(q) / q, finite as q -> 0.
    static double shapeDerivOverQ(double q) noexcept {
        if (q < 1.0) {
            return -3.0 + 2.25 * q;
        }
        if (q < 2.0) {
            const double t = 2.0 - q;
            return -0.75 * t * t / q;
        }
        return 0.0;
    }
    /// f(q) and f'(q)/q without a branch, for 0 <= q < 2 (a pair inside the support), for one
    /// value or four lanes (core/Lanes.hpp): both pieces are computed and a select keeps one,
    /// so a vectorised pair loop needs no masked division (AVX2 has none). At q = 0 the
    /// unused outer piece of f'(q)/q is infinite and dropped by the select.
    template <class V>
    static V shapeInSupport(V q) noexcept {
        const V t = 2.0 - q;
        const V inner = 1.0 - 1.5 * q * q + 0.75 * q * q * q;
        const V outer = 0.25 * t * t * t;
        return selectLess(q, V(1.0), inner, outer);
    }
    template <class V>
    static V shapeDerivOverQInSupport(V q) noexcept {
        const V t = 2.0 - q;
        const V inner = -3.0 + 2.25 * q;
        const V outer = -0.75 * t * t / q;
        return selectLess(q, V(1.0), inner, outer);
    }
    /// f'(q).
    static double shapeDeriv(double q) noexcept {
        if (q < 1.0) {
            return q * (-3.0 + 2.25 * q);
        }
        if (q < 2.0) {
            const double t = 2.0 - q;
            return -0.75 * t * t;
        }
        return 0.0;
    }
};

struct WendlandC2Kernel {
    static constexpr std::string_view kId = "kernel.wendland_c2";
    static constexpr double kNorm = 7.0 / (4.0 * units::kPi);

    static double shape(double q) noexcept {
        if (q >= 2.0) {
            return 0.0;
        }
        const double t = 1.0 - 0.5 * q;
        const double t2 = t * t;
        return t2 * t2 * (1.0 + 2.0 * q);
    }
    /// f'(q)/q = -5 (1 - q/2)^3.
    static double shapeDerivOverQ(double q) noexcept {
        if (q >= 2.0) {
            return 0.0;
        }
        const double t = 1.0 - 0.5 * q;
        return -5.0 * t * t * t;
    }
    /// The same without the support test, for 0 <= q < 2 (CubicSplineKernel says why).
    template <class V>
    static V shapeInSupport(V q) noexcept {
        const V t = 1.0 - 0.5 * q;
        const V t2 = t * t;
        return t2 * t2 * (1.0 + 2.0 * q);
    }
    template <class V>
    static V shapeDerivOverQInSupport(V q) noexcept {
        const V t = 1.0 - 0.5 * q;
        return -5.0 * t * t * t;
    }
    static double shapeDeriv(double q) noexcept { return q * shapeDerivOverQ(q); }
};

struct WendlandC4Kernel {
    static constexpr std::string_view kId = "kernel.wendland_c4";
    static constexpr double kNorm = 9.0 / (4.0 * units::kPi);

    static double shape(double q) noexcept {
        if (q >= 2.0) {
            return 0.0;
        }
        const double t = 1.0 - 0.5 * q;
        const double t2 = t * t;
        return t2 * t2 * t2 * (1.0 + 3.0 * q + (35.0 / 12.0) * q * q);
    }
    /// f'(q)/q = -(14/3) (1 - q/2)^5 (1 + 5q/2).
    static double shapeDerivOverQ(double q) noexcept {
        if (q >= 2.0) {
            return 0.0;
        }
        const double t = 1.0 - 0.5 * q;
        const double t2 = t * t;
        return -(14.0 / 3.0) * t2 * t2 * t * (1.0 + 2.5 * q);
    }
    /// The same without the support test, for 0 <= q < 2 (CubicSplineKernel says why).
    template <class V>
    static V shapeInSupport(V q) noexcept {
        const V t = 1.0 - 0.5 * q;
        const V t2 = t * t;
        return t2 * t2 * t2 * (1.0 + 3.0 * q + (35.0 / 12.0) * q * q);
    }
    template <class V>
    static V shapeDerivOverQInSupport(V q) noexcept {
        const V t = 1.0 - 0.5 * q;
        const V t2 = t * t;
        return -(14.0 / 3.0) * t2 * t2 * t * (1.0 + 2.5 * q);
    }
    static double shapeDeriv(double q) noexcept { return q * shapeDerivOverQ(q); }
};

/// The dimensional kernel functions for any of the shape structs above.
template <class Shape>
struct Kernel2D {
    using ShapeType = Shape;
    static constexpr std::string_view kId = Shape::kId;

    /// W(q, h) [1/mm^2].
    static double value(double q, double h) noexcept {
        return Shape::kNorm * Shape::shape(q) / (h * h);
    }
    /// dW/dr = (1/h) dW/dq [1/mm^3] (<= 0).
    static double dWdr(double q, double h) noexcept {
        return Shape::kNorm * Shape::shapeDeriv(q) / (h * h * h);
    }
    /// (1/r) dW/dr [1/mm^4]: grad_i W_ij = gradOverR * (x_i - x_j), finite at r = 0.
    static double gradOverR(double q, double h) noexcept {
        return Shape::kNorm * Shape::shapeDerivOverQ(q) / (h * h * h * h);
    }
    /// dW/dh at fixed separation [1/mm^3]: W = kNorm f(r/h)/h^2 gives
    /// dW/dh = -kNorm (2 f + q f') / h^3.
    static double dWdh(double q, double h) noexcept {
        return -Shape::kNorm * (2.0 * Shape::shape(q) + q * Shape::shapeDeriv(q)) / (h * h * h);
    }
};

using CubicSpline = Kernel2D<CubicSplineKernel>;
using WendlandC2 = Kernel2D<WendlandC2Kernel>;
using WendlandC4 = Kernel2D<WendlandC4Kernel>;

/// Calls f(kernel) with the kernel struct (CubicSpline, WendlandC2 or WendlandC4) that `type`
/// names, and returns what f returns. Use it outside the pair loop:
///   withKernel(type, [&](auto kernel) { for (...) w += m * kernel.value(q, h); });
template <class F>
decltype(auto) withKernel(KernelType type, F&& f) {
    switch (type) {
    case KernelType::CubicSpline:
        return f(CubicSpline{});
    case KernelType::WendlandC2:
        return f(WendlandC2{});
    case KernelType::WendlandC4:
        return f(WendlandC4{});
    }
    throw std::invalid_argument("withKernel: unknown KernelType " +
                                std::to_string(static_cast<int>(type)));
}

/// Parses "cubic_spline", "wendland_c2", "wendland_c4" (the kId without "kernel.");
/// throws std::invalid_argument listing the accepted names.
inline KernelType kernelTypeFromName(std::string_view name) {
    if (name == "cubic_spline") {
        return KernelType::CubicSpline;
    }
    if (name == "wendland_c2") {
        return KernelType::WendlandC2;
    }
    if (name == "wendland_c4") {
        return KernelType::WendlandC4;
    }
    throw std::invalid_argument("unknown SPH kernel '" + std::string(name) +
                                "' (expected cubic_spline, wendland_c2 or wendland_c4)");
}

} // namespace hvi::sph
