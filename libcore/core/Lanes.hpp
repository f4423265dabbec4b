// Four doubles computed as one (a 256-bit AVX vector), for the loops that are written once for
// a lane type: `double` (one value, a plain or `omp simd` loop) or `Lanes4` (four, where the
// build has AVX, HVI_HAVE_LANES4). The arithmetic is IEEE double in each lane, as the scalar
// code's; what differs between the two is only the order of the sums a loop reduces.
// The free functions (selectLess, anyLess, maxOf, sqrtOf, sumOf) exist for both types, so a
// function template over the lane type compiles unchanged for either.
#pragma once

#include <algorithm>
#include <cmath>

#if defined(__AVX__)
#include <immintrin.h>
#define HVI_HAVE_LANES4 1
#else
#define HVI_HAVE_LANES4 0
#endif

namespace hvi {

/// a < b ? x : y, without a branch.
inline double selectLess(double a, double b, double x, double y) {
    return a < b ? x : y;
}
/// Whether a < b (in any lane).
inline bool anyLess(double a, double b) {
    return a < b;
}
inline double maxOf(double a, double b) {
    return std::max(a, b);
}
inline double sqrtOf(double x) {
    return std::sqrt(x);
}
/// The lanes' sum (one lane: itself).
inline double sumOf(double x) {
    return x;
}
/// Stores the lanes at p, p + 1, ... (no alignment asked).
inline void storeTo(double* p, double x) {
    *p = x;
}

#if HVI_HAVE_LANES4

struct Lanes4 {
    __m256d v;
    Lanes4() = default;
    explicit Lanes4(__m256d x) : v(x) {}
    Lanes4(double x) : v(_mm256_set1_pd(x)) {} // NOLINT: a scalar is every lane's value
    Lanes4& operator+=(Lanes4 o) {
        v = _mm256_add_pd(v, o.v);
        return *this;
    }
    Lanes4& operator-=(Lanes4 o) {
        v = _mm256_sub_pd(v, o.v);
        return *this;
    }
};

inline Lanes4 operator+(Lanes4 a, Lanes4 b) {
    return Lanes4(_mm256_add_pd(a.v, b.v));
}
inline Lanes4 operator-(Lanes4 a, Lanes4 b) {
    return Lanes4(_mm256_sub_pd(a.v, b.v));
}
inline Lanes4 operator*(Lanes4 a, Lanes4 b) {
    return Lanes4(_mm256_mul_pd(a.v, b.v));
}
inline Lanes4 operator/(Lanes4 a, Lanes4 b) {
    return Lanes4(_mm256_div_pd(a.v, b.v));
}
inline Lanes4 operator-(Lanes4 a) {
    return Lanes4(_mm256_xor_pd(a.v, _mm256_set1_pd(-0.0)));
}
inline Lanes4 operator+(Lanes4 a, double b) {
    return a + Lanes4(b);
}
inline Lanes4 operator+(double a, Lanes4 b) {
    return Lanes4(a) + b;
}
inline Lanes4 operator-(Lanes4 a, double b) {
    return a - Lanes4(b);
}
inline Lanes4 operator-(double a, Lanes4 b) {
    return Lanes4(a) - b;
}
inline Lanes4 operator*(Lanes4 a, double b) {
    return a * Lanes4(b);
}
inline Lanes4 operator*(double a, Lanes4 b) {
    return Lanes4(a) * b;
}
inline Lanes4 operator/(Lanes4 a, double b) {
    return a / Lanes4(b);
}
inline Lanes4 operator/(double a, Lanes4 b) {
    return Lanes4(a) / b;
}

/// Lane by lane: a < b ? x : y (ordered, quiet: a NaN compares false, as in the scalar code).
inline Lanes4 selectLess(Lanes4 a, Lanes4 b, Lanes4 x, Lanes4 y) {
    return Lanes4(_mm256_blendv_pd(y.v, x.v, _mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)));
}
/// Whether a < b in any lane (ordered: a NaN compares false).
inline bool anyLess(Lanes4 a, Lanes4 b) {
    return _mm256_movemask_pd(_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)) != 0;
}
/// Lane by lane: a > b ? a : b, as std::max(b, a) for doubles with no NaN.
inline Lanes4 maxOf(Lanes4 a, Lanes4 b) {
    return Lanes4(_mm256_max_pd(b.v, a.v));
}
inline Lanes4 sqrtOf(Lanes4 x) {
    return Lanes4(_mm256_sqrt_pd(x.v));
}
/// ((l0 + l1) + l2) + l3: one fixed order.
inline double sumOf(Lanes4 x) {
    alignas(32) double l[4];
    _mm256_store_pd(l, x.v);
    return ((l[0] + l[1]) + l[2]) + l[3];
}
inline void storeTo(double* p, Lanes4 x) {
    _mm256_storeu_pd(p, x.v);
}
/// The largest lane.
inline double maxLane(Lanes4 x) {
    alignas(32) double l[4];
    _mm256_store_pd(l, x.v);
    return std::max(std::max(l[0], l[1]), std::max(l[2], l[3]));
}

/// Four 4-double rows (a, b, c, d) transposed in place into four columns: on return a holds
/// the rows' first values, b their second, c their third, d their fourth.
inline void transpose4(Lanes4& a, Lanes4& b, Lanes4& c, Lanes4& d) {
    const __m256d t0 = _mm256_unpacklo_pd(a.v, b.v); // a0 b0 a2 b2
    const __m256d t1 = _mm256_unpackhi_pd(a.v, b.v); // a1 b1 a3 b3
    const __m256d t2 = _mm256_unpacklo_pd(c.v, d.v); // c0 d0 c2 d2
    const __m256d t3 = _mm256_unpackhi_pd(c.v, d.v); // c1 d1 c3 d3
    a.v = _mm256_permute2f128_pd(t0, t2, 0x20);
    b.v = _mm256_permute2f128_pd(t1, t3, 0x20);
    c.v = _mm256_permute2f128_pd(t0, t2, 0x31);
    d.v = _mm256_permute2f128_pd(t1, t3, 0x31);
}

#endif

} // namespace hvi
