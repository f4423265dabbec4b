// Mie-Grueneisen EOS against results that do not come from its own formula: the
// Rankine-Hugoniot jump conditions of a linear Us-up Hugoniot, the thermodynamic definition of
// the sound speed (finite differences along an isentrope), and its documented limits.
#include "Tolerance.hpp"
#include "material/eos/MieGruneisen.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

using hvi::material::EosState;
using hvi::material::MieGruneisen;
using hvi::test::near;

namespace {

// Al 6061-T6, Steinberg 1996 (data/hydro_materials.json); b = 0.48 variant as in Spheral's
// aluminium set, to exercise the volume-correction terms.
MieGruneisen al(double b = 0.0) {
    return MieGruneisen{.referenceDensity = 2.703,
                        .bulkSoundSpeed = 5.24,
                        .hugoniotSlope = 1.40,
                        .gruneisenGamma = 1.97,
                        .volumeCorrection = b};
}

// c^2 = (dP/drho)_s by a central difference along the isentrope de = (P/rho^2) drho.
double isentropicSlope(const MieGruneisen& eos, double rho, double e) {
    const double h = 1.0e-5 * rho;
    const double p = eos.pressure(rho, e);
    const double de = p / (rho * rho) * h;
    return (eos.pressure(rho + h, e + de) - eos.pressure(rho - h, e - de)) / (2.0 * h);
}

} // namespace

TEST(MieGruneisen, HugoniotStatesGiveJumpConditionPressure) {
    for (double b : {0.0, 0.48}) {
        const MieGruneisen eos = al(b);
        for (double up : {1.0, 3.0}) {
            // Jump conditions: mass rho0 Us = rho (Us - up), momentum P = rho0 Us up, energy
            // e = P/2 (1/rho0 - 1/rho), with Us = c0 + s up.
            const double us = eos.bulkSoundSpeed + eos.hugoniotSlope * up;
            const double rho = eos.referenceDensity * us / (us - up);
            const double pH = eos.referenceDensity * us * up;
            const double eH = 0.5 * pH * (1.0 / eos.referenceDensity - 1.0 / rho);
            // The form is algebraically P_H + rho Gamma (e - e_H); only round-off (~1e-15)
            // separates the two, so 1e-9 relative catches any error in the form itself.
            EXPECT_TRUE(near("P on Hugoniot, up=" + std::to_string(up) + " b=" + std::to_string(b),
                             eos.pressure(rho, eH), pH, 0.0, 1e-9));
        }
    }
}

TEST(MieGruneisen, ReferenceStateHasZeroPressureAndBulkSoundSpeed) {
    const MieGruneisen eos = al();
    const EosState s = eos.evaluate(eos.referenceDensity, 0.0);
    EXPECT_EQ(s.pressure, 0.0); // mu = 0 and e = 0 exactly: every term is an exact zero
    // c^2 = c0^2 at the reference state by construction of the fit; round-off only.
    EXPECT_TRUE(near("c^2(rho0, 0)", s.soundSpeedSquared, 5.24 * 5.24, 0.0, 1e-14));
}

TEST(MieGruneisen, ContinuousAcrossMuZero) {
    for (double b : {0.0, 0.48}) {
        const MieGruneisen eos = al(b);
        const double e = 0.7; // non-zero so the Grueneisen term is exercised
        const double delta = 1.0e-12;
        const EosState above = eos.evaluate(eos.referenceDensity * (1.0 + delta), e);
        const EosState below = eos.evaluate(eos.referenceDensity * (1.0 - delta), e);
        // Across 2e-12 in mu, P moves by (dP/dmu) 2e-12 ~ 2e-10 GPa if continuous; a jump in
        // either branch's constant term would be O(1). 1e-9 GPa separates the two cases.
        EXPECT_TRUE(near("P jump at mu=0", above.pressure, below.pressure, 1e-9, 0.0));
        // c^2 continuity checks dP/drho (C1 of the cold curve) and the b e term.
        EXPECT_TRUE(
            near("c^2 jump at mu=0", above.soundSpeedSquared, below.soundSpeedSquared, 1e-8, 0.0));
    }
}

TEST(MieGruneisen, SoundSpeedIsTheIsentropicDerivative) {
    for (double b : {0.0, 0.48}) {
        const MieGruneisen eos = al(b);
        // Compression and mild expansion (where the floor is inactive), cold and hot.
        for (double ratio : {0.85, 0.95, 1.05, 1.3, 1.8, 2.4}) {
            for (double e : {0.0, 0.5, 4.0}) {
                const double rho = ratio * eos.referenceDensity;
                // Central difference, step 1e-5 rho: truncation ~1e-10 relative, round-off
                // ~1e-10; 1e-6 relative leaves margin yet catches any wrong derivative term
                // (the smallest, b e, is ~1 % of c^2).
                EXPECT_TRUE(near("c^2 at rho/rho0=" + std::to_string(ratio) +
                                     " e=" + std::to_string(e) + " b=" + std::to_string(b),
                                 eos.evaluate(rho, e).soundSpeedSquared,
                                 isentropicSlope(eos, rho, e), 0.0, 1e-6));
            }
        }
    }
}

TEST(MieGruneisen, SoundSpeedPositiveAndFiniteFromHalfToTwoAndAHalfRho0) {
    for (double b : {0.0, 0.48}) {
        const MieGruneisen eos = al(b);
        for (int i = 0; i <= 200; ++i) {
            const double rho = eos.referenceDensity * (0.5 + 2.0 * i / 200.0);
            for (double e : {0.0, 0.1, 1.0, 10.0}) {
                const EosState s = eos.evaluate(rho, e);
                EXPECT_TRUE(std::isfinite(s.pressure)) << "rho=" << rho << " e=" << e;
                EXPECT_TRUE(std::isfinite(s.soundSpeedSquared)) << "rho=" << rho << " e=" << e;
                EXPECT_GT(s.soundSpeedSquared, 0.0) << "rho=" << rho << " e=" << e;
            }
        }
    }
}

TEST(MieGruneisen, DeepTensionUsesTheDocumentedFloor) {
    const MieGruneisen eos = al();
    // At rho = 0.5 rho0, e = 0: c^2 = c0^2 (1 + Gamma0 mu / (1+mu)^2) = c0^2 (1 - 3.94) < 0.
    const EosState s = eos.evaluate(0.5 * eos.referenceDensity, 0.0);
    const double floor = MieGruneisen::kDefaultSoundSpeedFloorFraction * eos.bulkSoundSpeed;
    EXPECT_DOUBLE_EQ(s.soundSpeedSquared, floor * floor);
    // Pressure is not floored: P = rho0 c0^2 mu (tension is for the failure model to limit).
    EXPECT_TRUE(near("P at rho0/2", s.pressure, -0.5 * 2.703 * 5.24 * 5.24, 0.0, 1e-14));
}

TEST(MieGruneisen, CompressionBeyondTheCapStaysFiniteAndContinuous) {
    const MieGruneisen eos = al();
    const double muCap =
        (1.0 - MieGruneisen::kMinHugoniotDenominator) / (eos.hugoniotSlope - 1.0); // 2.0
    const double rhoCap = eos.referenceDensity * (1.0 + muCap);
    const double delta = 1.0e-9 * rhoCap;
    const EosState below = eos.evaluate(rhoCap - delta, 1.0);
    const EosState above = eos.evaluate(rhoCap + delta, 1.0);
    // P ~ 4e3 GPa and dP/drho ~ 1e4 there, so 2e-9 rhoCap moves P by ~1e-4 relative 1e-8;
    // a missing tangent continuation would jump by O(P).
    EXPECT_TRUE(near("P across cap", above.pressure, below.pressure, 0.0, 1e-7));
    EXPECT_TRUE(
        near("c^2 across cap", above.soundSpeedSquared, below.soundSpeedSquared, 0.0, 1e-6));
    // Past the singularity of the unguarded form (mu = 2.5) everything stays finite.
    for (double ratio : {3.5, 4.0, 10.0}) {
        const EosState s = eos.evaluate(ratio * eos.referenceDensity, 1.0);
        EXPECT_TRUE(std::isfinite(s.pressure) && s.pressure > below.pressure) << ratio;
        EXPECT_TRUE(std::isfinite(s.soundSpeedSquared) && s.soundSpeedSquared > 0.0) << ratio;
    }
}

TEST(MieGruneisen, NanInputIsNotHiddenByTheFloor) {
    const EosState s = al().evaluate(std::nan(""), 0.0);
    EXPECT_TRUE(std::isnan(s.pressure));
    EXPECT_TRUE(std::isnan(s.soundSpeedSquared));
}

TEST(MieGruneisen, BatchMatchesPointwiseAndChecksLengths) {
    const MieGruneisen eos = al(0.48);
    const std::vector<double> rho{1.5, 2.703, 3.5, 5.0};
    const std::vector<double> e{0.0, 0.2, 1.0, 3.0};
    std::vector<double> p(4), c2(4);
    hvi::material::evaluateEos(eos, rho, e, p, c2);
    for (std::size_t i = 0; i < rho.size(); ++i) {
        const EosState s = eos.evaluate(rho[i], e[i]);
        EXPECT_EQ(p[i], s.pressure); // same code path: bitwise equal
        EXPECT_EQ(c2[i], s.soundSpeedSquared);
    }
    std::vector<double> shortOut(3);
    EXPECT_THROW(hvi::material::evaluateEos(eos, rho, e, shortOut, c2), std::invalid_argument);
}

namespace {

// Tillotson's aluminium expanded-branch constants (Melosh 1989, App. II; the built-in
// Al6061-T6-Tillotson set and workflows/materials/expanded-states.json).
MieGruneisen alExpanded() {
    MieGruneisen eos = al();
    eos.expansion = {.gasGamma = 0.5,
                     .alpha = 5.0,
                     .beta = 5.0,
                     .incipientVaporEnergy = 3.0,
                     .completeVaporEnergy = 13.9};
    return eos;
}

} // namespace

TEST(MieGruneisenExpansion, ValuesMatchAnIndependentEvaluation) {
    // Reference values: the file comment's form evaluated in mpmath at 40 digits, c^2 from
    // mpmath's own numerical derivatives of that P (not from the analytic derivatives coded
    // here); the C++ differs by round-off (P) and by the 1e-13-level cancellation in c^2.
    const MieGruneisen eos = alExpanded();
    struct Case {
        double rho, e, p, c2;
        const char* region;
    };
    for (const Case& c :
         {Case{2.16, 20.0, 80.404176239100201, 157.03606732187676, "hot expanded"},
          Case{2.16, 8.0, 28.889894310964092, 59.529176022232336, "blend"},
          Case{1.3515, 50.0, 35.35210493995329, 61.659075315631938, "hot, half density"}}) {
        const EosState s = eos.evaluate(c.rho, c.e);
        EXPECT_TRUE(near(std::string("P ") + c.region, s.pressure, c.p, 0.0, 1e-12));
        EXPECT_TRUE(near(std::string("c^2 ") + c.region, s.soundSpeedSquared, c.c2, 0.0, 1e-10));
    }
    // Cold expanded states keep the solid form (below E_iv nothing changes).
    EXPECT_EQ(eos.pressure(1.3515, 1.0), al().pressure(1.3515, 1.0));
    // Hot debris at half density: the solid form's 229 GPa (its thermal term does not fall
    // with density) against the branch's 35 GPa.
    EXPECT_TRUE(
        near("solid form at half density", al().pressure(1.3515, 50.0), 229.1365536, 0.0, 1e-12));
}

TEST(MieGruneisenExpansion, ContinuousAcrossRho0AndTheVaporisationEnergies) {
    const MieGruneisen eos = alExpanded();
    const double d = 1.0e-10;
    const double rho0 = eos.referenceDensity;
    // A jump would be O(10) GPa; continuity leaves ~ dP/drho * 2e-10 ~ 1e-8.
    EXPECT_TRUE(near("P across rho0, e=20", eos.pressure(rho0 * (1 + d), 20.0),
                     eos.pressure(rho0 * (1 - d), 20.0), 1e-7, 0.0));
    for (double eEdge : {3.0, 13.9}) {
        EXPECT_TRUE(near("P across e=" + std::to_string(eEdge), eos.pressure(2.0, eEdge + d),
                         eos.pressure(2.0, eEdge - d), 1e-7, 0.0));
    }
}

TEST(MieGruneisenExpansion, SoundSpeedIsTheIsentropicDerivative) {
    const MieGruneisen eos = alExpanded();
    for (double rho : {2.4, 2.0, 1.5, 0.8}) {
        for (double e : {5.0, 20.0, 50.0}) {
            // Central differences with h = 1e-5 rho: truncation ~1e-10 relative, round-off
            // ~1e-11 / 1e-5; 1e-6 relative is far below any error in a derivative term.
            // Where the blend keeps much of the solid's tension the slope is negative and
            // the documented floor (0.1 c0)^2 applies (rho 0.8, e 5).
            const double floor2 = std::pow(0.1 * eos.bulkSoundSpeed, 2);
            EXPECT_TRUE(near("c^2 rho=" + std::to_string(rho) + " e=" + std::to_string(e),
                             eos.evaluate(rho, e).soundSpeedSquared,
                             std::max(isentropicSlope(eos, rho, e), floor2), 0.0, 1e-6));
        }
    }
}

TEST(MieGruneisenExpansion, TendsToTheGasOfGrueneisenParameterAAtLowDensity) {
    const MieGruneisen eos = alExpanded();
    // At rho0 / 20, x = 19 and exp(-alpha x^2) = exp(-1805) underflows: P = a rho e exactly,
    // and c^2 = a (1 + a) e, the ideal gas of gamma = 1 + a.
    const double rho = eos.referenceDensity / 20.0;
    const EosState s = eos.evaluate(rho, 20.0);
    EXPECT_TRUE(near("P / (rho e)", s.pressure / (rho * 20.0), 0.5, 0.0, 1e-14));
    EXPECT_TRUE(near("c^2", s.soundSpeedSquared, 0.5 * 1.5 * 20.0, 0.0, 1e-14));
    EXPECT_TRUE(eos.describesExpandedStates());
    EXPECT_FALSE(al().describesExpandedStates());
}

#if HVI_HAVE_LANES4
// The four-lane form that the solver's pressure loop uses (MaterialPackage.tpp) must give each
// lane the bits of the one-point evaluate(), so that vectorising changes no result: states in
// expansion, at mu = 0, in compression and beyond the compression cap, mixed in one vector.
TEST(MieGruneisen, FourLanesGiveTheOnePointBits) {
    const double rho0 = 2.703;
    const std::vector<double> ratios = {0.3, 0.62, 0.999, 1.0, 1.0001, 1.2, 1.55, 2.2, 3.4, 3.9};
    const std::vector<double> energies = {-1.3, 0.0, 0.02, 4.9, 37.0};
    for (double b : {0.0, 0.48}) {
        for (double slope : {1.40, 1.0}) { // 1.0: no compression cap
            MieGruneisen eos = al(b);
            eos.hugoniotSlope = slope;
            std::vector<double> rho, e;
            for (double x : ratios) {
                for (double en : energies) {
                    rho.push_back(x * rho0);
                    e.push_back(en);
                }
            }
            std::size_t compared = 0;
            for (std::size_t k = 0; k + 4 <= rho.size(); ++k) { // every window of four
                const auto st = eos.evaluateSolid(hvi::Lanes4(_mm256_loadu_pd(&rho[k])),
                                                  hvi::Lanes4(_mm256_loadu_pd(&e[k])));
                alignas(32) double p[4], c2[4];
                _mm256_store_pd(p, st.pressure.v);
                _mm256_store_pd(c2, st.soundSpeedSquared.v);
                for (std::size_t j = 0; j < 4; ++j) {
                    const EosState one = eos.evaluate(rho[k + j], e[k + j]);
                    EXPECT_EQ(p[j], one.pressure) << "rho " << rho[k + j] << " e " << e[k + j];
                    EXPECT_EQ(c2[j], one.soundSpeedSquared)
                        << "rho " << rho[k + j] << " e " << e[k + j];
                    ++compared;
                }
            }
            EXPECT_EQ(compared, 4 * (rho.size() - 3));
        }
    }
}
#endif
