// Tillotson EOS: values computed independently (sympy, exact rationals, from Melosh 1989's
// form), continuity at the region boundaries, and c^2 against the isentropic derivative in
// every region.
#include "Tolerance.hpp"
#include "material/eos/Tillotson.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

using hvi::material::Tillotson;
using hvi::test::near;

namespace {

// Melosh 1989 aluminium (data/hydro_materials.json "Al6061-T6-Tillotson").
const Tillotson kAl{.referenceDensity = 2.70,
                    .bulkModulusA = 75.2,
                    .nonlinearModulusB = 65.0,
                    .referenceEnergy = 5.0,
                    .incipientVaporEnergy = 3.0,
                    .completeVaporEnergy = 13.9,
                    .smallA = 0.5,
                    .smallB = 1.63,
                    .alpha = 5.0,
                    .beta = 5.0};

double isentropicSlope(double rho, double e) {
    const double h = 1.0e-6 * rho;
    const double p = kAl.pressure(rho, e);
    const double de = p / (rho * rho) * h;
    return (kAl.pressure(rho + h, e + de) - kAl.pressure(rho - h, e - de)) / (2.0 * h);
}

} // namespace

TEST(Tillotson, ValuesInEachRegionMatchAnIndependentEvaluation) {
    // Reference values: the formulas of Melosh (1989) App. II evaluated in sympy with the
    // constants as exact rationals, printed to 17 digits; the C++ should differ by round-off
    // only, so 1e-13 relative.
    struct Case {
        double rho, e, p;
        const char* region;
    };
    for (const Case& c : {Case{3.24, 1.0, 23.897151219512195, "compressed"},
                          Case{2.16, 20.0, 25.553299375579451, "hot expanded"},
                          Case{2.16, 8.0, 7.5170887328347185, "blend"},
                          Case{2.16, 1.0, -8.6774857142857143, "cold expanded"}}) {
        EXPECT_TRUE(near(std::string("P ") + c.region, kAl.pressure(c.rho, c.e), c.p, 0.0, 1e-13));
    }
    // Sound speed, same sympy session: c^2 = dP/drho + P/rho^2 dP/de of each branch.
    EXPECT_TRUE(near("c^2 compressed", kAl.evaluate(3.24, 1.0).soundSpeedSquared,
                     52.718464319481188, 0.0, 1e-13));
    EXPECT_TRUE(near("c^2 hot expanded", kAl.evaluate(2.16, 20.0).soundSpeedSquared,
                     27.580805603921161, 0.0, 1e-13));
}

TEST(Tillotson, ReferenceState) {
    const auto s = kAl.evaluate(kAl.referenceDensity, 0.0);
    EXPECT_EQ(s.pressure, 0.0);
    // c0^2 = A / rho0 at the reference state.
    EXPECT_TRUE(near("c^2(rho0, 0)", s.soundSpeedSquared, 75.2 / 2.70, 0.0, 1e-14));
}

TEST(Tillotson, ContinuousAcrossRegionBoundaries) {
    const double d = 1.0e-10;
    // Across rho0 at a hot energy (compressed -> hot expanded formula).
    const double rho0 = kAl.referenceDensity;
    // P changes by ~dP/drho * 2e-10 ~ 1e-8 if continuous; a jump would be O(1) GPa.
    EXPECT_TRUE(near("P across rho0, e=20", kAl.pressure(rho0 * (1 + d), 20.0),
                     kAl.pressure(rho0 * (1 - d), 20.0), 1e-7, 0.0));
    // Across E_iv and E_cv in expansion.
    for (double eEdge : {kAl.incipientVaporEnergy, kAl.completeVaporEnergy}) {
        EXPECT_TRUE(near("P across e=" + std::to_string(eEdge), kAl.pressure(2.0, eEdge + d),
                         kAl.pressure(2.0, eEdge - d), 1e-7, 0.0));
    }
}

TEST(Tillotson, SoundSpeedIsTheIsentropicDerivativeInEveryRegion) {
    struct Case {
        double rho, e;
    };
    // compressed, cold expanded, blend, hot expanded
    for (const Case& c :
         {Case{3.5, 2.0}, Case{2.5, 1.0}, Case{2.4, 6.0}, Case{2.4, 30.0}, Case{1.5, 20.0}}) {
        const auto s = kAl.evaluate(c.rho, c.e);
        // Central difference with step 1e-6 rho: error well below 1e-6 relative.
        EXPECT_TRUE(near("c^2 rho=" + std::to_string(c.rho) + " e=" + std::to_string(c.e),
                         s.soundSpeedSquared, isentropicSlope(c.rho, c.e), 0.0, 1e-6));
    }
}

TEST(Tillotson, SoundSpeedPositiveAndFinite) {
    for (int i = 0; i <= 100; ++i) {
        const double rho = kAl.referenceDensity * (0.5 + 2.0 * i / 100.0);
        for (double e : {0.0, 1.0, 5.0, 10.0, 50.0}) {
            const auto s = kAl.evaluate(rho, e);
            EXPECT_TRUE(std::isfinite(s.pressure)) << rho << " " << e;
            EXPECT_TRUE(std::isfinite(s.soundSpeedSquared) && s.soundSpeedSquared > 0.0)
                << rho << " " << e;
        }
    }
}
