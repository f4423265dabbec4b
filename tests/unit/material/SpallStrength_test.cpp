// The spall criterion: a largest principal stress beyond sigma_sp fails a point; the principal
// stress of an RZ deviator; the power-law rate term against a hand evaluation.
#include "Tolerance.hpp"
#include "material/failure/SpallStrength.hpp"

#include <cmath>
#include <gtest/gtest.h>

using hvi::material::SpallStrength;
using hvi::material::StressDeviator;
using hvi::test::near;

namespace {

/// An instantaneous criterion (the rate and cumulative parts left out unless set).
SpallStrength spallAt(double strengthGPa, double rateExponent = 0.0,
                      double referenceStrainRatePerUs = 1.0e-6) {
    SpallStrength s;
    s.strengthGPa = strengthGPa;
    s.rateExponent = rateExponent;
    s.referenceStrainRatePerUs = referenceStrainRatePerUs;
    return s;
}

/// Whether a sound point fails at once (the instantaneous criterion; no step, so no
/// cumulative damage).
bool failsAtOnce(const SpallStrength& spall, const StressDeviator& s, double pressure,
                 double strainRatePerUs) {
    return spall.damageAfter(0.0, s, pressure, strainRatePerUs, 0.0) == 1.0;
}

} // namespace

TEST(SpallStrength, PrincipalTensionBeyondTheStrengthFails) {
    const SpallStrength spall = spallAt(1.2);
    const StressDeviator none{};
    EXPECT_FALSE(failsAtOnce(spall, none, -1.19, 1.0));
    EXPECT_FALSE(failsAtOnce(spall, none, -1.2, 1.0)); // at the strength: not beyond it
    EXPECT_TRUE(failsAtOnce(spall, none, -1.21, 1.0));
    EXPECT_FALSE(failsAtOnce(spall, none, 5.0, 1.0)); // compression never spalls
    // Uniaxial strain yielding in tension: S_zz = 2/3 Y, S_rr = S_thth = -1/3 Y; with
    // Y = 0.3 GPa a mean tension of 1.05 GPa is a longitudinal tension of 1.25 GPa.
    const StressDeviator yielding{.zz = 0.2, .rr = -0.1, .rz = 0.0};
    EXPECT_TRUE(near("sigma_1", yielding.maxPrincipal() + 1.05, 1.25, 0.0, 1e-15));
    EXPECT_TRUE(failsAtOnce(spall, yielding, -1.05, 1.0));
    EXPECT_FALSE(failsAtOnce(spall, yielding, -0.95, 1.0));
}

TEST(SpallStrength, PrincipalValuesOfAnRzDeviator) {
    // Pure shear in the plane: principal values +-tau; the hoop value 0.
    EXPECT_TRUE(near("shear", StressDeviator{.zz = 0.0, .rr = 0.0, .rz = 0.3}.maxPrincipal(), 0.3,
                     0.0, 1e-15));
    // In-plane compression both ways: the hoop component is the largest.
    EXPECT_TRUE(near("hoop", StressDeviator{.zz = -0.1, .rr = -0.2, .rz = 0.0}.maxPrincipal(), 0.3,
                     0.0, 1e-15));
}

TEST(SpallStrength, PowerLawRateTerm) {
    // Kanel's exponent for aluminium, about 0.06; reference 1e4 /s = 1e-2 /us.
    const SpallStrength spall = spallAt(1.0, 0.06, 1.0e-2);
    // 1e6 /s: a factor 100^0.06 = 1.3183.
    EXPECT_TRUE(near("sigma_sp(1e6/s)", spall.strengthAt(1.0), std::pow(100.0, 0.06), 0.0, 1e-14));
    EXPECT_TRUE(near("1.3183", spall.strengthAt(1.0), 1.3183, 0.0, 5e-5));
    // At and below the reference rate: the reference strength.
    EXPECT_EQ(spall.strengthAt(1.0e-2), 1.0);
    EXPECT_EQ(spall.strengthAt(1.0e-5), 1.0);
    EXPECT_TRUE(failsAtOnce(spall, StressDeviator{}, -1.2, 1.0e-3));
    EXPECT_FALSE(failsAtOnce(spall, StressDeviator{}, -1.2, 1.0));
}

TEST(SpallStrength, CumulativeDamageFailsAfterTheTulerButcherTime) {
    // Held at sigma_1 = 1.5 GPa with sigma_0 = 1.0, lambda = 2, K_f = 0.2 GPa^2 us: the damage
    // rate is 0.25 / 0.2 = 1.25 /us, so the point fails after t_f = K_f / (sigma_1 - sigma_0)^2
    // = 0.8 us, to within one step.
    SpallStrength spall = spallAt(3.0);
    spall.cumulative = hvi::material::CumulativeSpall{
        .thresholdGPa = 1.0, .exponent = 2.0, .criticalIntegral = 0.2};
    const double dt = 0.001;
    double damage = 0.0, t = 0.0;
    while (damage < 1.0 && t < 10.0) {
        damage = spall.damageAfter(damage, StressDeviator{}, -1.5, 1.0, dt);
        t += dt;
    }
    EXPECT_TRUE(near("t_f", t, 0.8, 1.01 * dt, 0.0)); // rounding may add the one step
    // Below the threshold nothing accumulates; beyond the ceiling the point fails at once.
    EXPECT_EQ(spall.damageAfter(0.3, StressDeviator{}, -0.99, 1.0, dt), 0.3);
    EXPECT_EQ(spall.damageAfter(0.0, StressDeviator{}, -3.01, 1.0, dt), 1.0);
    // lambda = 1: the increment is linear in the excess.
    spall.cumulative->exponent = 1.0;
    EXPECT_TRUE(near("linear", spall.damageAfter(0.0, StressDeviator{}, -1.5, 1.0, 0.1),
                     0.1 * 0.5 / 0.2, 0.0, 1e-15));
}

TEST(SpallStrength, WithoutTheCumulativePartTheDamageIsUntouched) {
    const SpallStrength spall = spallAt(2.0);
    EXPECT_EQ(spall.damageAfter(0.4, StressDeviator{}, -1.99, 1.0, 0.1), 0.4);
    EXPECT_EQ(spall.damageAfter(0.4, StressDeviator{}, -2.01, 1.0, 0.1), 1.0);
}
