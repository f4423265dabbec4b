// The density cut-off of MaterialPackage::updatePressure (material/MaterialPackage.tpp): below
// sph.min_density_ratio a point is fragmented. With an EOS that describes hot expanded states
// (here Mie-Grueneisen with Tillotson's expanded branch, as workflows/materials/
// expanded-states.json gives it) a hot point keeps its gas pressure, which is continuous
// across the cut-off; a cold one carries nothing. Without the branch the point carries no
// pressure and keeps the sound speed of the cut-off density (as before the branch existed).
#include "TestPaths.hpp"
#include "Tolerance.hpp"
#include "material/MaterialLibrary.hpp"
#include "material/MaterialPackage.hpp"
#include "sph/ParticleSet.hpp"

#include <gtest/gtest.h>

using namespace hvi;

namespace {

/// Al 6061-T6 as built in, or as the repository's expanded-states overlay patches it.
material::MaterialSpec aluminium(bool expandedStates) {
    const auto& builtin = material::MaterialLibrary::builtin();
    if (!expandedStates) {
        return builtin.get("Al6061-T6");
    }
    return material::MaterialLibrary::fromFile(
               test::sourcePath("workflows/materials/expanded-states.json").string(), &builtin)
        .get("Al6061-T6");
}

struct Point {
    double p, cs;
};

/// Pressure and sound speed of one failed particle at (rho, e) in a body of `spec` whose
/// cut-off is half the reference density.
Point pressureOf(const material::MaterialSpec& spec, double rho, double e) {
    sph::ParticleSet ps;
    ps.add(0.0, 1.0, 0.0, 0.0, 1.0, 0.1, rho, e, 0);
    ps.enableStrength();
    ps.damage[0] = 1.0;
    const material::MaterialPackage package({{.spec = &spec,
                                              .strength = true,
                                              .minDensity = 0.5 * spec.referenceDensity,
                                              .maxDensity = 2.25 * spec.referenceDensity,
                                              .first = 0,
                                              .count = 1}});
    package.updatePressure(ps);
    return {ps.p[0], ps.cs[0]};
}

} // namespace

TEST(MaterialPackageCutOff, HotExpandedPointKeepsAContinuousGasPressure) {
    const auto spec = aluminium(true);
    const double cut = 0.5 * spec.referenceDensity;
    const auto& eos = std::get<material::MieGruneisen>(spec.eos);
    for (double e : {20.0, 50.0}) {
        const Point above = pressureOf(spec, cut * (1 + 1e-9), e);
        const Point below = pressureOf(spec, cut * (1 - 1e-9), e);
        // Continuous: a jump would be the whole pressure (tens of GPa).
        EXPECT_TRUE(test::near("P across the cut-off, e=" + std::to_string(e), below.p, above.p,
                               1e-6, 0.0));
        EXPECT_GT(below.p, 10.0);
        // Below the cut-off: the EOS at the point's own density, its gas sound speed.
        const Point deep = pressureOf(spec, 0.2 * spec.referenceDensity, e);
        const auto st = eos.evaluate(0.2 * spec.referenceDensity, e);
        EXPECT_EQ(deep.p, st.pressure);
        EXPECT_EQ(deep.cs, std::sqrt(st.soundSpeedSquared));
    }
    // A cold fragment carries nothing (its EOS pressure there is tension).
    EXPECT_EQ(pressureOf(spec, 0.4 * spec.referenceDensity, 0.5).p, 0.0);
}

TEST(MaterialPackageCutOff, WithoutTheBranchAnExpandedPointCarriesNoPressure) {
    const auto spec = aluminium(false);
    const double cut = 0.5 * spec.referenceDensity;
    const auto& eos = std::get<material::MieGruneisen>(spec.eos);
    const Point below = pressureOf(spec, 0.4 * spec.referenceDensity, 50.0);
    EXPECT_EQ(below.p, 0.0);
    // ... and the sound speed of the cut-off density (about 27 km/s for 50 MJ/kg: what made
    // hot debris set the time step, docs/notebook/stray-states.md).
    EXPECT_EQ(below.cs, std::sqrt(eos.evaluate(cut, 50.0).soundSpeedSquared));
    EXPECT_GT(below.cs, 25.0);
}
