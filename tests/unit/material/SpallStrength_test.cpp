// The spall criterion: a largest principal stress beyond sigma_sp fails a point; the principal
// stress of an RZ deviator; the power-law rate term against a hand evaluation.
#include "Tolerance.hpp"
#include "material/failure/SpallStrength.hpp"

#include <cmath>
#include <gtest/gtest.h>

using hvi::material::SpallStrength;
using hvi::material::StressDeviator;
using hvi::test::near;

TEST(SpallStrength, PrincipalTensionBeyondTheStrengthFails) {
    const SpallStrength spall{.strengthGPa = 1.2};
    const StressDeviator none{};
    EXPECT_FALSE(spall.exceeded(none, -1.19, 1.0));
    EXPECT_FALSE(spall.exceeded(none, -1.2, 1.0)); // at the strength: not beyond it
    EXPECT_TRUE(spall.exceeded(none, -1.21, 1.0));
    EXPECT_FALSE(spall.exceeded(none, 5.0, 1.0)); // compression never spalls
    // Uniaxial strain yielding in tension: S_zz = 2/3 Y, S_rr = S_thth = -1/3 Y; with
    // Y = 0.3 GPa a mean tension of 1.05 GPa is a longitudinal tension of 1.25 GPa.
    const StressDeviator yielding{.zz = 0.2, .rr = -0.1, .rz = 0.0};
    EXPECT_TRUE(near("sigma_1", yielding.maxPrincipal() + 1.05, 1.25, 0.0, 1e-15));
    EXPECT_TRUE(spall.exceeded(yielding, -1.05, 1.0));
    EXPECT_FALSE(spall.exceeded(yielding, -0.95, 1.0));
}

TEST(SpallStrength, PrincipalValuesOfAnRzDeviator) {
    // Pure shear in the plane: principal values +-tau; the hoop value 0.
    EXPECT_TRUE(near("shear", StressDeviator{.zz = 0.0, .rr = 0.0, .rz = 0.3}.maxPrincipal(), 0.3,
                     0.0, 1e-15));
    // In-plane compression both ways: the hoop component is the largest.
    EXPECT_TRUE(near("hoop", StressDeviator{.zz = -0.1, .rr = -0.2, .rz = 0.0}.maxPrincipal(),
                     0.3, 0.0, 1e-15));
}

TEST(SpallStrength, PowerLawRateTerm) {
    // Kanel's exponent for aluminium, about 0.06; reference 1e4 /s = 1e-2 /us.
    const SpallStrength spall{.strengthGPa = 1.0, .rateExponent = 0.06,
                              .referenceStrainRatePerUs = 1.0e-2};
    // 1e6 /s: a factor 100^0.06 = 1.3183.
    EXPECT_TRUE(near("sigma_sp(1e6/s)", spall.strengthAt(1.0), std::pow(100.0, 0.06), 0.0, 1e-14));
    EXPECT_TRUE(near("1.3183", spall.strengthAt(1.0), 1.3183, 0.0, 5e-5));
    // At and below the reference rate: the reference strength.
    EXPECT_EQ(spall.strengthAt(1.0e-2), 1.0);
    EXPECT_EQ(spall.strengthAt(1.0e-5), 1.0);
    EXPECT_TRUE(spall.exceeded(StressDeviator{}, -1.2, 1.0e-3));
    EXPECT_FALSE(spall.exceeded(StressDeviator{}, -1.2, 1.0));
}
