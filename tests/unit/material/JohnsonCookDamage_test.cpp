// Johnson-Cook damage with the source study's Al 6061-T6 constants: the eps_f table of
// hydrocode-notes.md section 4.3, the D3 sign (eps_f falls with triaxiality), the floor,
// the clamps, accumulation and the failed state.
#include "Tolerance.hpp"
#include "material/failure/JohnsonCookDamage.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using hvi::material::JohnsonCookDamage;
using hvi::material::StressDeviator;
using hvi::test::near;

namespace {

// shared/validation/thesis_cases.json: D1..D5 = -0.77, 1.45, -0.47, 0, 1.6.
const JohnsonCookDamage kAl{.d1 = -0.77, .d2 = 1.45, .d3 = -0.47, .d4 = 0.0, .d5 = 1.6};
constexpr double kQuasiStatic = 1.0e-6; // the reference rate 1/s in 1/us

/// One material point under the damage law: D, the tensile-excursion state, eps_p.
struct Point {
    double damage = 0.0;
    double tensionOnset = 0.0;
    double plasticStrain = 0.0;
    /// A plastic increment at pressure P and sigma_eq [GPa], quasi-static, room temperature.
    double flow(const JohnsonCookDamage& model, double increment, double pressure,
                double vonMises) {
        damage = model.damageAfter(damage, tensionOnset, plasticStrain, increment, pressure,
                                   vonMises, kQuasiStatic, 0.0);
        plasticStrain += increment;
        return damage;
    }
};

/// The damage after one increment from D, for a point that has not flowed before.
double damageAfter(const JohnsonCookDamage& model, double damage, double increment, double pressure,
                   double vonMises) {
    Point point{.damage = damage};
    return point.flow(model, increment, pressure, vonMises);
}

} // namespace

TEST(JohnsonCookDamage, FailureStrainTableOfTheNotes) {
    struct Row {
        double sigmaStar, epsF;
    };
    // The notes give eps_f to three decimals; the brief's 0.002 bound is loose, and half a
    // unit of the last printed digit (0.0005) is the tightest the table itself supports.
    for (const Row& row : {Row{-1.0 / 3.0, 0.926}, Row{0.0, 0.680}, Row{1.0 / 3.0, 0.470},
                           Row{2.0 / 3.0, 0.290}, Row{1.0, 0.136}}) {
        EXPECT_TRUE(near("eps_f at sigma*=" + std::to_string(row.sigmaStar),
                         kAl.failureStrain(row.sigmaStar, kQuasiStatic, 0.0), row.epsF, 5e-4, 0.0));
    }
    // And to full precision against sympy (-0.77 + 1.45 exp(-0.47/3) = 0.46973406...).
    EXPECT_TRUE(near("eps_f(1/3) exact", kAl.failureStrain(1.0 / 3.0, kQuasiStatic, 0.0),
                     0.46973406, 1e-8, 0.0));
}

TEST(JohnsonCookDamage, FailureStrainFallsAsTriaxialityRises) {
    // The D3 sign pitfall: with exp(-D3 sigma*) the curve would rise instead.
    double previous = std::numeric_limits<double>::infinity();
    for (double s = -1.5; s <= 1.3; s += 0.1) {
        const double epsF = kAl.failureStrain(s, kQuasiStatic, 0.0);
        EXPECT_LT(epsF, previous) << "sigma*=" << s;
        previous = epsF;
    }
}

TEST(JohnsonCookDamage, FloorAtHighTriaxiality) {
    // The fit reaches the 0.01 floor at sigma* = ln(0.78/1.45)/(-0.47) = 1.319 and crosses
    // zero at ln(0.77/1.45)/(-0.47) = 1.3467.
    EXPECT_TRUE(near("eps_f(1.30), above the floor", kAl.failureStrain(1.30, kQuasiStatic, 0.0),
                     -0.77 + 1.45 * std::exp(-0.47 * 1.30), 0.0, 1e-12));
    EXPECT_GT(kAl.failureStrain(1.30, kQuasiStatic, 0.0), kAl.minFailureStrain);
    EXPECT_EQ(kAl.failureStrain(1.34, kQuasiStatic, 0.0), kAl.minFailureStrain); // fit 0.0024
    EXPECT_EQ(kAl.failureStrain(1.35, kQuasiStatic, 0.0), kAl.minFailureStrain); // fit < 0
    EXPECT_EQ(kAl.failureStrain(1.5, kQuasiStatic, 0.0), kAl.minFailureStrain);
    EXPECT_EQ(kAl.failureStrain(50.0, kQuasiStatic, 0.0), kAl.minFailureStrain);
    EXPECT_GT(kAl.minFailureStrain, 0.0);
}

TEST(JohnsonCookDamage, TriaxialityClampsAndHydrostaticStates) {
    // sigma* = -P / sigma_eq: tension (P < 0) positive.
    EXPECT_TRUE(near("sigma* uniaxial tension", kAl.triaxiality(-0.1, 0.3), 1.0 / 3.0, 0.0, 1e-15));
    EXPECT_EQ(kAl.triaxiality(-1.0, 0.1), 1.5);   // clamped above
    EXPECT_EQ(kAl.triaxiality(100.0, 0.3), -1.5); // strong shock: clamped below
    EXPECT_EQ(kAl.triaxiality(-1.0, 0.0), 1.5);   // hydrostatic tension
    EXPECT_EQ(kAl.triaxiality(1.0, 0.0), -1.5);   // hydrostatic compression
    EXPECT_EQ(kAl.triaxiality(0.0, 0.0), 0.0);    // unstressed
    // Deep compression: exp(D3 sigma*) would overflow unclamped; eps_f stays finite.
    const double epsF = kAl.failureStrain(-1.0e4, kQuasiStatic, 0.0);
    EXPECT_TRUE(
        near("eps_f at the lower clamp", epsF, -0.77 + 1.45 * std::exp(0.47 * 1.5), 0.0, 1e-14));
}

TEST(JohnsonCookDamage, RateAndTemperatureTerms) {
    // 4340 steel (Johnson & Cook 1985): D4 = 0.002, D5 = 0.61.
    const JohnsonCookDamage steel{.d1 = 0.05, .d2 = 3.44, .d3 = -2.12, .d4 = 0.002, .d5 = 0.61};
    const double base = 0.05 + 3.44 * std::exp(-2.12 * 0.5);
    // 1000 /s = 1e-3 /us.
    EXPECT_TRUE(near("rate term", steel.failureStrain(0.5, 1.0e-3, 0.0),
                     base * (1.0 + 0.002 * std::log(1000.0)), 0.0, 1e-14));
    EXPECT_TRUE(
        near("below reference rate", steel.failureStrain(0.5, 1.0e-9, 0.0), base, 0.0, 1e-15));
    EXPECT_TRUE(near("T* = 0.4", steel.failureStrain(0.5, kQuasiStatic, 0.4),
                     base * (1.0 + 0.61 * 0.4), 0.0, 1e-14));
}

TEST(JohnsonCookDamage, AccumulationIsCappedAtOne) {
    EXPECT_TRUE(near("D", JohnsonCookDamage::accumulate(0.2, 0.068, 0.68), 0.3, 0.0, 1e-15));
    EXPECT_EQ(JohnsonCookDamage::accumulate(0.95, 0.5, 0.68), 1.0);
}

TEST(JohnsonCookDamage, FailedMaterialCarriesNoShearAndNoTension) {
    StressDeviator s{0.2, -0.1, 0.05};
    double p = -0.8;
    JohnsonCookDamage::applyFailedState(1.0, s, p);
    EXPECT_EQ(s.vonMises(), 0.0);
    EXPECT_EQ(p, 0.0);
    // Compression is kept.
    s = {0.2, -0.1, 0.05};
    p = 3.0;
    JohnsonCookDamage::applyFailedState(1.0, s, p);
    EXPECT_EQ(s.vonMises(), 0.0);
    EXPECT_EQ(p, 3.0);
    // Not yet failed: untouched.
    s = {0.2, -0.1, 0.05};
    p = -0.8;
    JohnsonCookDamage::applyFailedState(0.999, s, p);
    EXPECT_EQ(s.zz, 0.2);
    EXPECT_EQ(p, -0.8);
}

// Bao & Wierzbicki's cut-off: no damage below sigma* = -1/3 (a compressive shock, uniaxial
// compression beyond it), the same increment as accumulate() above it.
TEST(JohnsonCookDamage, NoDamageBelowTheCompressionCutoff) {
    EXPECT_EQ(kAl.compressionCutoff, -1.0 / 3.0);
    // Just above the cut-off (sigma* = -0.333): damage accumulates.
    const double aboveCutoff = damageAfter(kAl, 0.0, 0.01, 0.0999, 0.3);
    EXPECT_TRUE(near("D at sigma* = -0.333", aboveCutoff,
                     0.01 / kAl.failureStrain(-0.333, kQuasiStatic, 0.0), 0.0, 1e-12));
    // A shock: P = 10 GPa, sigma_eq = 0.3 GPa.
    EXPECT_EQ(damageAfter(kAl, 0.25, 0.05, 10.0, 0.3), 0.25);
    // Just below the cut-off.
    EXPECT_EQ(damageAfter(kAl, 0.25, 0.05, 0.1001, 0.3), 0.25);
    // Tension: the JC increment.
    EXPECT_TRUE(near("D in tension", damageAfter(kAl, 0.0, 0.01, -0.1, 0.3),
                     0.01 / kAl.failureStrain(1.0 / 3.0, kQuasiStatic, 0.0), 0.0, 1e-12));
}

// With the upper clamp at the fit's calibrated end (sigma* = 1 for the 6061-T6 fit in the
// library), eps_f beyond it stays at eps_f(1) = 0.136 instead of the 0.01 floor.
TEST(JohnsonCookDamage, UpperClampHoldsTheLastCalibratedFailureStrain) {
    JohnsonCookDamage al = kAl;
    al.maxTriaxiality = 1.0;
    const double atOne = -0.77 + 1.45 * std::exp(-0.47);
    EXPECT_TRUE(near("eps_f(3) -> eps_f(1)",
                     al.failureStrain(al.triaxiality(-0.9, 0.3), kQuasiStatic, 0.0), atOne, 0.0,
                     1e-14));
    EXPECT_TRUE(near("hydrostatic tension",
                     al.failureStrain(al.triaxiality(-0.9, 0.0), kQuasiStatic, 0.0), atOne, 0.0,
                     1e-14));
}

// Closure below the cut-off (Kanvinde and Deierlein's cyclic void growth in the Johnson-Cook
// form). A plane-stress equibiaxial strain cycle, the state of a wall cycled by in-plane waves:
// sigma* = +2/3 in tension (P = -0.2 GPa, sigma_eq = 0.3 GPa), -2/3 in compression, the same
// plastic increment each half.
namespace {
constexpr double kSigmaEq = 0.3;
constexpr double kTensionP = -0.2, kCompressionP = 0.2; // sigma* = +-2/3
double epsF23() {
    return -0.77 + 1.45 * std::exp(-0.47 * 2.0 / 3.0); // the fit at sigma* = 2/3, 0.29
}
double afterCycles(const JohnsonCookDamage& model, int cycles, double increment) {
    Point point;
    for (int k = 0; k < cycles; ++k) {
        point.flow(model, increment, kTensionP, kSigmaEq);
        point.flow(model, increment, kCompressionP, kSigmaEq);
    }
    return point.damage;
}
/// The first cycle (0-based) whose tensile half fails the point, or -1 within maxCycles.
int failingCycle(const JohnsonCookDamage& model, int maxCycles, double increment) {
    Point point;
    for (int k = 0; k < maxCycles; ++k) {
        if (point.flow(model, increment, kTensionP, kSigmaEq) >= 1.0) {
            return k;
        }
        point.flow(model, increment, kCompressionP, kSigmaEq);
    }
    return -1;
}
} // namespace

TEST(JohnsonCookDamage, ClosureLeavesMonotonicPathsAlone) {
    JohnsonCookDamage closing = kAl;
    closing.compressionClosure = 1.0;
    Point open, shut;
    for (int k = 0; k < 100; ++k) {
        open.flow(kAl, 0.002, kTensionP, kSigmaEq);
        shut.flow(closing, 0.002, kTensionP, kSigmaEq);
    }
    EXPECT_EQ(shut.damage, open.damage);
    EXPECT_TRUE(near("D after 0.2 of tension", open.damage, 0.2 / epsF23(), 0.0, 1e-12));
}

TEST(JohnsonCookDamage, ClosureUndoesSymmetricCycles) {
    // Without closure each cycle adds its tensile half: 30 cycles of 0.005 fail the point (the
    // Johnson-Cook sum reaches 30 x 0.005 / 0.29 > 0.5 and goes on); with full closure each
    // cycle ends where it began; with half, half the tensile increment stays.
    EXPECT_TRUE(near("no closure", afterCycles(kAl, 30, 0.005), 30 * 0.005 / epsF23(), 0.0, 1e-12));
    JohnsonCookDamage closing = kAl;
    closing.compressionClosure = 1.0;
    EXPECT_TRUE(near("full closure", afterCycles(closing, 30, 0.005), 0.0, 1e-15, 0.0));
    closing.compressionClosure = 0.5;
    EXPECT_TRUE(near("half closure", afterCycles(closing, 30, 0.005), 30 * 0.5 * 0.005 / epsF23(),
                     0.0, 1e-12));
}

TEST(JohnsonCookDamage, ClosureStopsAtZeroAndNeverMendsFailedMaterial) {
    JohnsonCookDamage closing = kAl;
    closing.compressionClosure = 1.0;
    // A shock (P = 10 GPa) after some damage: closed to zero, not below.
    EXPECT_EQ(damageAfter(closing, 0.25, 0.05, 10.0, kSigmaEq), 0.0);
    EXPECT_EQ(damageAfter(closing, 1.0, 0.05, kCompressionP, kSigmaEq), 1.0);
    // Between the cut-off and zero triaxiality damage still grows (shear fracture).
    EXPECT_GT(damageAfter(closing, 0.25, 0.01, 0.05, kSigmaEq), 0.25);
}

// The degradation of the critical damage, exp(-lambda eps_p,0) (Kanvinde and Deierlein 2007).
// A monotonic tension path never flowed below the cut-off (eps_p,0 = 0): it fails where
// Johnson-Cook does, at eps_f, whatever lambda.
TEST(JohnsonCookDamage, DegradationLeavesMonotonicPathsAlone) {
    JohnsonCookDamage degrading = kAl;
    degrading.compressionClosure = 1.0;
    degrading.cyclicDegradation = 2.0;
    Point point;
    while (point.flow(degrading, 0.001, kTensionP, kSigmaEq) < 1.0) {
    }
    EXPECT_EQ(point.tensionOnset, 0.0);
    EXPECT_TRUE(near("eps_p at failure", point.plasticStrain, epsF23(), 0.001, 0.0));
}

// Compression first (a shock: eps_p = 0.3 below the cut-off), then tension: the excursion
// starts at eps_p,0 = 0.3 and fails at D = exp(-lambda 0.3), after eps_f exp(-lambda 0.3) of
// tensile plastic strain, to within one increment.
TEST(JohnsonCookDamage, DegradationCountsTheStrainBeforeTheTensileExcursion) {
    JohnsonCookDamage degrading = kAl;
    degrading.cyclicDegradation = 1.0;
    Point point;
    for (int k = 0; k < 300; ++k) {
        point.flow(degrading, 0.001, 10.0, kSigmaEq);
    }
    EXPECT_EQ(point.tensionOnset, JohnsonCookDamage::kCompressiveFlow);
    EXPECT_EQ(point.damage, 0.0);
    const double compressed = point.plasticStrain;
    while (point.flow(degrading, 0.001, kTensionP, kSigmaEq) < 1.0) {
    }
    EXPECT_TRUE(near("eps_p,0", point.tensionOnset, compressed, 1e-12, 0.0));
    EXPECT_TRUE(near("tensile eps_p at failure", point.plasticStrain - compressed,
                     epsF23() * std::exp(-1.0 * compressed), 0.001, 0.0));
}

// Symmetric cycles with full closure: each tensile half starts from D = 0 at eps_p,0 = 2 k d
// (cycle k, increment d a half) and ends at D = d / eps_f, so the point fails in the first
// cycle with d / eps_f >= exp(-lambda 2 k d), k = ceil(ln(eps_f / d) / (2 lambda d)): 169 for
// d = 0.01, lambda = 1 (the bound is 168.4, far enough from an integer for rounding). Without
// degradation the cycles never fail.
TEST(JohnsonCookDamage, DegradedCyclesFailAfterTheClosedFormCount) {
    JohnsonCookDamage degrading = kAl;
    degrading.compressionClosure = 1.0;
    const double d = 0.01;
    EXPECT_EQ(failingCycle(degrading, 2000, d), -1);
    degrading.cyclicDegradation = 1.0;
    const int expected = static_cast<int>(std::ceil(std::log(epsF23() / d) / (2.0 * d)));
    EXPECT_EQ(expected, 169);
    EXPECT_EQ(failingCycle(degrading, 2000, d), expected);
}
