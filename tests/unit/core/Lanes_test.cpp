// core/Lanes.hpp: four doubles computed as one must give, lane by lane, what the same
// expression gives on doubles (IEEE arithmetic, the selects' NaN rule, the square root), the
// lanes' sum must be the one fixed order ((l0 + l1) + l2) + l3, and transpose4 must turn four
// rows into four columns. The SPH pair loop (sph/SphHydro.cpp) relies on all of it; the
// kernels' lane forms are checked against their one-value forms here too.
#include "core/Lanes.hpp"
#include "sph/Kernel.hpp"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

#if HVI_HAVE_LANES4

using hvi::Lanes4;

namespace {

using Four = std::array<double, 4>;

Lanes4 load(const Four& x) {
    return Lanes4(_mm256_loadu_pd(x.data()));
}

Four lanes(Lanes4 x) {
    Four out;
    _mm256_storeu_pd(out.data(), x.v);
    return out;
}

} // namespace

TEST(Lanes4, ArithmeticIsEachLanesDoubleArithmetic) {
    const Four a{1.5, -2.25, 3.0e-7, 4.0e5}, b{0.3, 7.0, -1.0e-3, 2.0};
    const Four sum = lanes(load(a) + load(b)), difference = lanes(load(a) - load(b));
    const Four product = lanes(load(a) * load(b)), quotient = lanes(load(a) / load(b));
    const Four negated = lanes(-load(a)), scaled = lanes(2.5 * load(a) - 1.0);
    const Four root = lanes(hvi::sqrtOf(load(b) * load(b)));
    for (int l = 0; l < 4; ++l) {
        EXPECT_EQ(sum[l], a[l] + b[l]);
        EXPECT_EQ(difference[l], a[l] - b[l]);
        EXPECT_EQ(product[l], a[l] * b[l]);
        EXPECT_EQ(quotient[l], a[l] / b[l]);
        EXPECT_EQ(negated[l], -a[l]);
        EXPECT_EQ(scaled[l], 2.5 * a[l] - 1.0);
        EXPECT_EQ(root[l], std::sqrt(b[l] * b[l]));
    }
}

TEST(Lanes4, SelectAndMaxFollowTheScalarRules) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Four a{1.0, 2.0, nan, -1.0}, b{2.0, 2.0, 0.0, -3.0};
    const Four x{10.0, 20.0, 30.0, 40.0}, y{-10.0, -20.0, -30.0, -40.0};
    const Four chosen = lanes(hvi::selectLess(load(a), load(b), load(x), load(y)));
    const Four larger = lanes(hvi::maxOf(load(b), load(Four{1.0, 5.0, -1.0, -2.0})));
    for (int l = 0; l < 4; ++l) {
        EXPECT_EQ(chosen[l], hvi::selectLess(a[l], b[l], x[l], y[l])) << "lane " << l;
    }
    EXPECT_EQ(larger, (Four{2.0, 5.0, 0.0, -2.0}));
}

TEST(Lanes4, SumsInOneFixedOrder) {
    // Chosen so that any other order of the four additions gives another double.
    const Four x{1.0e16, 1.0, -1.0e16, 1.0};
    EXPECT_EQ(hvi::sumOf(load(x)), ((x[0] + x[1]) + x[2]) + x[3]);
    EXPECT_NE(hvi::sumOf(load(x)), (x[0] + x[2]) + (x[1] + x[3]));
    EXPECT_EQ(hvi::maxLane(load(Four{-3.0, 7.0, 2.0, 6.5})), 7.0);
}

TEST(Lanes4, TransposeTurnsRowsIntoColumns) {
    Lanes4 a = load({0, 1, 2, 3}), b = load({10, 11, 12, 13});
    Lanes4 c = load({20, 21, 22, 23}), d = load({30, 31, 32, 33});
    hvi::transpose4(a, b, c, d);
    EXPECT_EQ(lanes(a), (Four{0, 10, 20, 30}));
    EXPECT_EQ(lanes(b), (Four{1, 11, 21, 31}));
    EXPECT_EQ(lanes(c), (Four{2, 12, 22, 32}));
    EXPECT_EQ(lanes(d), (Four{3, 13, 23, 33}));
}

template <class Shape>
void expectLanesMatchOneValue() {
    for (int k = 0; k < 500; ++k) {
        const Four q{0.004 * k, 0.004 * k + 0.001, 0.004 * k + 0.002, 0.004 * k + 0.003};
        const Four f = lanes(Shape::shapeInSupport(load(q)));
        const Four g = lanes(Shape::shapeDerivOverQInSupport(load(q)));
        for (int l = 0; l < 4; ++l) {
            const double scale = std::fabs(Shape::shapeDerivOverQInSupport(q[l])) + 1.0;
            EXPECT_NEAR(f[l], Shape::shapeInSupport(q[l]), 1e-15) << Shape::kId << " q " << q[l];
            EXPECT_NEAR(g[l], Shape::shapeDerivOverQInSupport(q[l]), 1e-15 * scale)
                << Shape::kId << " q " << q[l];
        }
    }
}

TEST(Lanes4, KernelShapesInLanesAreTheOneValueShapes) {
    expectLanesMatchOneValue<hvi::sph::CubicSplineKernel>();
    expectLanesMatchOneValue<hvi::sph::WendlandC2Kernel>();
    expectLanesMatchOneValue<hvi::sph::WendlandC4Kernel>();
}

#else

TEST(Lanes4, NotBuilt) {
    GTEST_SKIP() << "this build has no AVX: the pair loop takes one pair at a time";
}

#endif
