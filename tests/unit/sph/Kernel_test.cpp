// 2D SPH kernels: normalisation by quadrature (radial Gauss-Legendre and a particle-lattice
// sum), compact support, derivatives against finite differences, and continuity where the
// piecewise definitions join.
#include "Tolerance.hpp"
#include "sph/Kernel.hpp"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <string>

using namespace hvi::sph;
using hvi::test::near;

namespace {

constexpr double kPi = 3.14159265358979323846;

// 5-point Gauss-Legendre on [-1, 1]: exact for polynomials up to degree 9.
constexpr std::array<double, 5> kGlX{0.0, -0.5384693101056831, 0.5384693101056831,
                                     -0.9061798459386640, 0.9061798459386640};
constexpr std::array<double, 5> kGlW{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                     0.2369268850561891, 0.2369268850561891};

/// 2 pi int_0^{2h} W(r/h, h) r dr, with panels whose edges include q = 1 (the cubic
/// spline's joint). On each panel the integrand W r is a polynomial of degree <= 9 (cubic:
/// 4, C2: 6, C4: 9), so the rule is exact and only round-off remains.
template <class K>
double radialIntegral(double h) {
    const int panels = 40; // 20 per unit of q
    double sum = 0.0;
    for (int p = 0; p < panels; ++p) {
        const double a = kKernelSupport * h * p / panels;
        const double b = kKernelSupport * h * (p + 1) / panels;
        for (std::size_t i = 0; i < kGlX.size(); ++i) {
            const double r = 0.5 * (a + b) + 0.5 * (b - a) * kGlX[i];
            sum += 0.5 * (b - a) * kGlW[i] * K::value(r / h, h) * r;
        }
    }
    return 2.0 * kPi * sum;
}

/// sum_j W(|x_j|/h, h) dx^2 over a square lattice of spacing dx offset from the origin: the
/// SPH estimate of int W dA with unit-volume particles.
template <class K>
double latticeSum(double h, double dx, double offsetX, double offsetY) {
    const int n = static_cast<int>(std::ceil(kKernelSupport * h / dx)) + 2;
    double sum = 0.0;
    for (int i = -n; i <= n; ++i) {
        for (int j = -n; j <= n; ++j) {
            const double x = i * dx + offsetX;
            const double y = j * dx + offsetY;
            sum += K::value(std::hypot(x, y) / h, h);
        }
    }
    return sum * dx * dx;
}

template <class K>
class KernelTest : public ::testing::Test {};

using Kernels = ::testing::Types<CubicSpline, WendlandC2, WendlandC4>;
TYPED_TEST_SUITE(KernelTest, Kernels);

} // namespace

TYPED_TEST(KernelTest, IntegratesToOne) {
    using K = TypeParam;
    for (double h : {1.0, 0.0225, 3.7}) {
        // Exact rule: round-off only, far inside the brief's 1e-6.
        EXPECT_TRUE(near(std::string(K::kId) + " radial quadrature, h=" + std::to_string(h),
                         radialIntegral<K>(h), 1.0, 1e-12, 0.0));
    }
    // Lattice sum at 20 particles per h: the error is the kernel's Fourier transform at the
    // reciprocal lattice, below 1e-7 for these kernels; 1e-6 is the brief's quadrature bound.
    EXPECT_TRUE(near(std::string(K::kId) + " lattice sum",
                     latticeSum<K>(0.015, 0.015 / 20.0, 0.3e-4, 0.1e-4), 1.0, 1e-6, 0.0));
}

TYPED_TEST(KernelTest, VanishesOutsideTheSupport) {
    using K = TypeParam;
    for (double q : {2.0, 2.0000001, 2.5, 10.0}) {
        EXPECT_EQ(K::value(q, 0.7), 0.0) << q;
        EXPECT_EQ(K::dWdr(q, 0.7), 0.0) << q;
        EXPECT_EQ(K::gradOverR(q, 0.7), 0.0) << q;
        EXPECT_EQ(K::dWdh(q, 0.7), 0.0) << q;
    }
    EXPECT_GT(K::value(1.999, 0.7), 0.0);
}

TYPED_TEST(KernelTest, DerivativesMatchFiniteDifferences) {
    using K = TypeParam;
    const double h = 0.37;
    const double scale = 1.0 / (h * h * h); // magnitude of dW/dr and dW/dh
    for (double q = 0.05; q < 2.0; q += 0.1) {
        const double r = q * h;
        const double d = 1.0e-6 * h;
        const double fdR = (K::value((r + d) / h, h) - K::value((r - d) / h, h)) / (2.0 * d);
        // Central difference with step 1e-6 h: truncation ~1e-12, round-off ~1e-10 of scale.
        EXPECT_TRUE(near(std::string(K::kId) + " dW/dr at q=" + std::to_string(q), K::dWdr(q, h),
                         fdR, 1e-8 * scale, 0.0));
        // gradOverR is dW/dr divided by r (one expression per kernel, separately written).
        EXPECT_TRUE(near(std::string(K::kId) + " r * gradOverR at q=" + std::to_string(q),
                         r * K::gradOverR(q, h), K::dWdr(q, h), 1e-13 * scale, 1e-13));
        const double dh = 1.0e-6 * h;
        const double fdH =
            (K::value(r / (h + dh), h + dh) - K::value(r / (h - dh), h - dh)) / (2.0 * dh);
        EXPECT_TRUE(near(std::string(K::kId) + " dW/dh at q=" + std::to_string(q), K::dWdh(q, h),
                         fdH, 1e-8 * scale, 0.0));
    }
}

TYPED_TEST(KernelTest, GradientIsContinuousWhereThePiecesJoin) {
    using K = TypeParam;
    const double h = 1.0;
    const double eps = 1.0e-10;
    // q = 1 is a joint of the cubic spline only, q = 2 the support edge of all; W, dW/dq and
    // (1/r)dW/dr must all join. A slope of O(1) moves them by ~2e-10 across the gap.
    for (double joint : {1.0, 2.0}) {
        const std::string where = std::string(K::kId) + " at q=" + std::to_string(joint);
        EXPECT_TRUE(
            near("W " + where, K::value(joint - eps, h), K::value(joint + eps, h), 1e-9, 0.0));
        EXPECT_TRUE(
            near("dW/dr " + where, K::dWdr(joint - eps, h), K::dWdr(joint + eps, h), 1e-9, 0.0));
        EXPECT_TRUE(near("gradOverR " + where, K::gradOverR(joint - eps, h),
                         K::gradOverR(joint + eps, h), 1e-9, 0.0));
    }
}

TEST(Kernel, GradientOverRHasTheAnalyticLimitAtZero) {
    // f'(q)/q at q = 0: cubic -3, Wendland C2 -5, Wendland C4 -14/3 (times sigma / h^4).
    const double h = 0.5;
    const double h4 = h * h * h * h;
    EXPECT_TRUE(
        near("cubic", CubicSpline::gradOverR(0.0, h), -3.0 * 10.0 / (7.0 * kPi) / h4, 0.0, 1e-15));
    EXPECT_TRUE(
        near("C2", WendlandC2::gradOverR(0.0, h), -5.0 * 7.0 / (4.0 * kPi) / h4, 0.0, 1e-15));
    EXPECT_TRUE(near("C4", WendlandC4::gradOverR(0.0, h), -14.0 / 3.0 * 9.0 / (4.0 * kPi) / h4, 0.0,
                     1e-15));
}

TEST(Kernel, CubicSplinePeakValue) {
    // W(0, h) = 10 / (7 pi h^2): the normalisation the brief specifies.
    EXPECT_TRUE(
        near("W(0, 2)", CubicSpline::value(0.0, 2.0), 10.0 / (7.0 * kPi * 4.0), 0.0, 1e-15));
}

TEST(Kernel, DispatchSelectsTheNamedKernel) {
    const double q = 0.7;
    const double h = 0.3;
    auto value = [&](KernelType t) {
        return withKernel(t, [&](auto kernel) { return kernel.value(q, h); });
    };
    EXPECT_EQ(value(KernelType::CubicSpline), CubicSpline::value(q, h));
    EXPECT_EQ(value(KernelType::WendlandC2), WendlandC2::value(q, h));
    EXPECT_EQ(value(KernelType::WendlandC4), WendlandC4::value(q, h));
    EXPECT_EQ(kernelTypeFromName("wendland_c4"), KernelType::WendlandC4);
    EXPECT_EQ(kernelTypeFromName("cubic_spline"), KernelType::CubicSpline);
    EXPECT_THROW(kernelTypeFromName("quintic"), std::invalid_argument);
}

TYPED_TEST(KernelTest, BranchFreeFormsEqualTheBranchedOnesInsideTheSupport) {
    // The vectorised pair loop (SphHydro.cpp) evaluates the shapes without their piece tests;
    // inside the support they must be the same functions, the cubic spline's joint at q = 1
    // and the limit at q = 0 included.
    using Shape = typename TypeParam::ShapeType;
    for (int k = 0; k < 2000; ++k) {
        const double q = 1.0e-3 * k;
        const std::string where = std::string(Shape::kId) + " at q=" + std::to_string(q);
        EXPECT_TRUE(near("f " + where, Shape::shapeInSupport(q), Shape::shape(q), 1e-15, 1e-15));
        EXPECT_TRUE(near("f'/q " + where, Shape::shapeDerivOverQInSupport(q),
                         Shape::shapeDerivOverQ(q), 1e-15, 1e-15));
    }
}
