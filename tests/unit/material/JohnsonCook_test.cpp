// Johnson-Cook flow stress with the source study's Al 6061-T6 constants: hand values
// (computed in sympy to 15 digits), the rate floor and its units, and zero strength at melt.
#include "Tolerance.hpp"
#include "material/strength/JohnsonCook.hpp"

#include <cmath>
#include <gtest/gtest.h>

using hvi::material::JohnsonCookStrength;
using hvi::test::near;

namespace {

// shared/validation/thesis_cases.json: A 289.6 MPa, B 203.4 MPa, n 0.35, C 0.011, m 1.34.
const JohnsonCookStrength kAl{.yieldStress = 0.2896,
                              .hardeningModulus = 0.2034,
                              .hardeningExponent = 0.35,
                              .strainRateCoefficient = 0.011,
                              .thermalExponent = 1.34};

constexpr double kQuasiStatic = 1.0e-6; // 1/s in 1/us: the reference rate, rate factor 1

} // namespace

TEST(JohnsonCookStrength, HandValuesAtRoomTemperatureAndReferenceRate) {
    // A + B eps^n: 0.2896; 0.2896 + 0.2034 * 0.1^0.35 = 0.380455442643506; 0.2896 + 0.2034.
    // 1e-13 relative: the references carry 15 digits and the C++ is one pow and two flops.
    EXPECT_TRUE(near("Y(0)", kAl.flowStress(0.0, kQuasiStatic, 0.0), 0.2896, 0.0, 1e-13));
    EXPECT_TRUE(
        near("Y(0.1)", kAl.flowStress(0.1, kQuasiStatic, 0.0), 0.380455442643506, 0.0, 1e-13));
    EXPECT_TRUE(near("Y(1)", kAl.flowStress(1.0, kQuasiStatic, 0.0), 0.493, 0.0, 1e-13));
}

TEST(JohnsonCookStrength, ThermalFactorAtHalfMelt) {
    // 1 - 0.5^1.34 = 0.604979344068311.
    EXPECT_TRUE(near("1 - T*^m at T*=0.5", kAl.thermalFactor(0.5), 0.604979344068311, 0.0, 1e-13));
    EXPECT_TRUE(near("Y(0.1) at T*=0.5", kAl.flowStress(0.1, kQuasiStatic, 0.5),
                     0.380455442643506 * 0.604979344068311, 0.0, 1e-13));
}

TEST(JohnsonCookStrength, ZeroStrengthAtAndAboveMelt) {
    EXPECT_EQ(kAl.flowStress(0.5, 1.0, 1.0), 0.0);
    EXPECT_EQ(kAl.flowStress(0.5, 1.0, 1.7), 0.0);
    // Below room temperature the curve is not extrapolated upwards: T* clamps at 0.
    EXPECT_EQ(kAl.thermalFactor(-0.3), 1.0);
}

TEST(JohnsonCookStrength, RateTermUsesOnePerSecondAsReferenceInMicrosecondUnits) {
    // 1000 /s = 1e-3 /us: 1 + 0.011 ln(1000) = 1.07598530806880.
    EXPECT_TRUE(near("rate factor 1e3/s", kAl.rateFactor(1.0e-3), 1.07598530806880, 0.0, 1e-13));
    // Below the reference rate the factor is floored at 1, never below.
    EXPECT_EQ(kAl.rateFactor(1.0e-9), 1.0);
    EXPECT_EQ(kAl.rateFactor(0.0), 1.0);
    // A typical HVI rate of 1e6 /s = 1 /us: 1 + 0.011 ln(1e6).
    EXPECT_TRUE(
        near("rate factor 1e6/s", kAl.rateFactor(1.0), 1.0 + 0.011 * std::log(1.0e6), 0.0, 1e-15));
}

TEST(JohnsonCookStrength, NegativePlasticStrainReadsAsZeroAndNanPropagates) {
    EXPECT_EQ(kAl.hardening(-1e-12), kAl.yieldStress);
    EXPECT_TRUE(std::isnan(kAl.flowStress(std::nan(""), 1.0, 0.0)));
    EXPECT_TRUE(std::isnan(kAl.flowStress(0.1, std::nan(""), 0.0)));
}

TEST(JohnsonCookStrength, FlowStressNeverFallsBelowItsFloor) {
    // The floor A (1 - T*) lets the material update skip the flow stress of a point that is
    // elastic for certain, so it must hold at every state, to the bit, for m = 1 (where
    // 1 - T*^m equals it) and m > 1, and be 0 (no bound) where it cannot hold.
    for (const double m : {1.0, 1.03, 1.34, 1.7}) {
        JohnsonCookStrength jc = kAl;
        jc.thermalExponent = m;
        for (const double t : {-0.2, 0.0, 1e-9, 0.1, 0.37, 0.5, 0.93, 0.999999}) {
            const double floor = jc.flowStressFloor(t);
            EXPECT_GT(floor, 0.0) << "m " << m << " T* " << t;
            for (const double eps : {0.0, 1e-12, 0.01, 0.3, 2.0}) {
                for (const double rate : {0.0, kQuasiStatic, 1e-3, 1.0, 50.0}) {
                    EXPECT_LE(floor, jc.flowStress(eps, rate, t))
                        << "m " << m << " T* " << t << " eps " << eps << " rate " << rate;
                }
            }
        }
        EXPECT_EQ(jc.flowStressFloor(1.0), 0.0);
        EXPECT_EQ(jc.flowStressFloor(std::nan("")), 0.0);
    }
    JohnsonCookStrength soft = kAl;
    soft.thermalExponent = 0.8; // T*^m > T*: no cheap bound
    EXPECT_EQ(soft.flowStressFloor(0.5), 0.0);
    EXPECT_DOUBLE_EQ(kAl.flowStressFloor(0.0), 0.2896);
}
