// J2 radial return: lands exactly on the yield surface, keeps the direction, gives the
// consistent plastic strain increment, and counts the hoop (out-of-plane) component.
#include "Tolerance.hpp"
#include "material/strength/RadialReturn.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using hvi::material::radialReturn;
using hvi::material::StressDeviator;
using hvi::test::near;

namespace {

constexpr double kG = 27.6; // Al 6061-T6 shear modulus [GPa]

// Independent oracle: the 3D von Mises stress from principal values,
// sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2) / 2), with the in-plane principal values from Mohr's
// circle and s3 = S_thth.
double vonMisesFromPrincipal(const StressDeviator& s) {
    const double centre = 0.5 * (s.zz + s.rr);
    const double radius = std::hypot(0.5 * (s.zz - s.rr), s.rz);
    const double s1 = centre + radius;
    const double s2 = centre - radius;
    const double s3 = -(s.zz + s.rr);
    return std::sqrt(0.5 * ((s1 - s2) * (s1 - s2) + (s2 - s3) * (s2 - s3) + (s3 - s1) * (s3 - s1)));
}

} // namespace

TEST(RadialReturn, VonMisesMatchesPrincipalStressForm) {
    for (const StressDeviator& s : {StressDeviator{0.3, -0.1, 0.2}, StressDeviator{-0.5, 0.2, 0.0},
                                    StressDeviator{0.0, 0.0, 0.4}, StressDeviator{1.0, 1.0, 0.3}}) {
        // Two algebraically equal forms; round-off only.
        EXPECT_TRUE(near("sigma_eq", s.vonMises(), vonMisesFromPrincipal(s), 0.0, 1e-13));
    }
}

TEST(RadialReturn, HoopComponentCountsInJ2) {
    // S_zz = S_rr = a, S_rz = 0: the in-plane part alone is isotropic, but S_thth = -2a, so
    // the deviator is diag(a, a, -2a) and sigma_eq = 3|a| (uniaxial stress 3a along theta).
    const StressDeviator s{0.1, 0.1, 0.0};
    EXPECT_TRUE(near("sigma_eq of diag(a,a,-2a)", s.vonMises(), 0.3, 0.0, 1e-15));
    EXPECT_GT(s.vonMises(), 0.0);
    // Planar strain, pure shear S_xy = tau: sigma_eq = sqrt(3) tau (textbook).
    EXPECT_TRUE(near("pure shear", StressDeviator{0.0, 0.0, 0.2}.vonMises(), std::sqrt(3.0) * 0.2,
                     0.0, 1e-15));
}

TEST(RadialReturn, ReturnsExactlyOntoTheYieldSurfaceAlongTheSameDirection) {
    const double yield = 0.3;
    for (const StressDeviator& trial :
         {StressDeviator{0.4, -0.1, 0.25}, StressDeviator{0.3, 0.3, 0.0},
          StressDeviator{-1.2, 0.5, -0.7}}) {
        StressDeviator s = trial;
        const double sigma0 = trial.vonMises();
        ASSERT_GT(sigma0, yield);
        const double dEp = radialReturn(s, yield, kG);
        // Scaling by Y/sigma_eq is one multiply per component: 1e-12 is round-off with margin.
        EXPECT_TRUE(near("sigma_eq after return", s.vonMises(), yield, 0.0, 1e-12));
        const double k = yield / sigma0;
        EXPECT_TRUE(near("S_zz direction", s.zz, k * trial.zz, 1e-15, 1e-13));
        EXPECT_TRUE(near("S_rr direction", s.rr, k * trial.rr, 1e-15, 1e-13));
        EXPECT_TRUE(near("S_rz direction", s.rz, k * trial.rz, 1e-15, 1e-13));
        EXPECT_TRUE(near("d eps_p", dEp, (sigma0 - yield) / (3.0 * kG), 0.0, 1e-13));
    }
}

TEST(RadialReturn, ElasticStateIsLeftAlone) {
    StressDeviator s{0.1, -0.05, 0.02};
    const StressDeviator before = s;
    EXPECT_EQ(radialReturn(s, 0.3, kG), 0.0);
    EXPECT_EQ(s.zz, before.zz);
    EXPECT_EQ(s.rr, before.rr);
    EXPECT_EQ(s.rz, before.rz);
}

TEST(RadialReturn, ZeroYieldStressRemovesTheDeviator) {
    StressDeviator s{0.2, -0.1, 0.1};
    const double sigma0 = s.vonMises();
    EXPECT_TRUE(near("d eps_p", radialReturn(s, 0.0, kG), sigma0 / (3.0 * kG), 0.0, 1e-15));
    EXPECT_EQ(s.vonMises(), 0.0);
}

TEST(RadialReturn, BatchMatchesPointwiseAndAccumulatesPlasticStrain) {
    std::vector<double> szz{0.4, 0.05, -1.0}, srr{-0.1, 0.0, 0.5}, srz{0.25, 0.01, -0.7};
    const std::vector<double> yield{0.3, 0.3, 0.0};
    std::vector<double> ep{0.1, 0.2, 0.3};
    const std::vector<double> ep0 = ep;
    std::vector<StressDeviator> expected;
    std::vector<double> expectedDep;
    for (std::size_t i = 0; i < szz.size(); ++i) {
        StressDeviator s{szz[i], srr[i], srz[i]};
        expectedDep.push_back(radialReturn(s, yield[i], kG));
        expected.push_back(s);
    }
    radialReturn(szz, srr, srz, yield, kG, ep);
    for (std::size_t i = 0; i < szz.size(); ++i) {
        EXPECT_EQ(szz[i], expected[i].zz);
        EXPECT_EQ(srr[i], expected[i].rr);
        EXPECT_EQ(srz[i], expected[i].rz);
        EXPECT_EQ(ep[i], ep0[i] + expectedDep[i]);
    }
    std::vector<double> shortYield{0.3};
    EXPECT_THROW(radialReturn(szz, srr, srz, shortYield, kG, ep), std::invalid_argument);
}
