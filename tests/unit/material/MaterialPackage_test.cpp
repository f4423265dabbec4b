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

// updatePressure runs the Mie-Grueneisen bodies four points at a time (MaterialPackage.tpp);
// every point must get the p and cs it gets alone (one point, the one-at-a-time path), the
// cut-off rules included, and a deleted point keeps what it had. Thirteen points: three full
// vectors and a tail, with a deleted, failed, expanded and compressed point among them.
TEST(MaterialPackageCutOff, FourAtATimeGivesEveryPointItsOwnBits) {
    const auto spec = aluminium(false);
    const double rho0 = spec.referenceDensity;
    struct State {
        double rho, e, damage;
        bool alive;
    };
    const std::vector<State> states = {
        {rho0, 0.0, 0.0, true},        {1.3 * rho0, 2.0, 0.0, true},
        {0.95 * rho0, 0.1, 1.0, true}, {0.4 * rho0, 30.0, 0.3, true},
        {rho0, 0.0, 0.0, false},       {2.1 * rho0, 9.0, 1.0, true},
        {0.97 * rho0, 0.0, 0.5, true}, {0.45 * rho0, 0.2, 1.0, true},
        {1.02 * rho0, -0.3, 0.0, true}, {3.6 * rho0, 40.0, 0.0, true},
        {0.99 * rho0, 1.0, 1.0, true}, {1.6 * rho0, 5.0, 0.2, true},
        {0.8 * rho0, 0.05, 0.9, true}};
    const auto package = [&](std::size_t count) {
        return material::MaterialPackage({{.spec = &spec,
                                           .strength = true,
                                           .minDensity = 0.5 * rho0,
                                           .maxDensity = 2.25 * rho0,
                                           .first = 0,
                                           .count = count}});
    };
    const auto fill = [](sph::ParticleSet& ps, const State& s) {
        const std::size_t i = ps.size();
        ps.add(0.0, 1.0 + static_cast<double>(i), 0.0, 0.0, 1.0, 0.1, s.rho, s.e, 0);
    };
    sph::ParticleSet all;
    for (const State& s : states) {
        fill(all, s);
    }
    all.enableStrength();
    for (std::size_t i = 0; i < states.size(); ++i) {
        all.damage[i] = states[i].damage;
        all.alive[i] = states[i].alive ? 1 : 0;
        all.p[i] = -7.0; // what a deleted point must keep
        all.cs[i] = -7.0;
    }
    package(states.size()).updatePressure(all);
    std::vector<int32_t> items(states.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        items[i] = static_cast<int32_t>(i);
    }
    sph::ParticleSet listed = all;
    listed.p.assign(listed.size(), -7.0);
    listed.cs.assign(listed.size(), -7.0);
    package(states.size()).updatePressure(listed, items);
    for (std::size_t i = 0; i < states.size(); ++i) {
        sph::ParticleSet one;
        fill(one, states[i]);
        one.enableStrength();
        one.damage[0] = states[i].damage;
        package(1).updatePressure(one);
        const double p = states[i].alive ? one.p[0] : -7.0;
        const double cs = states[i].alive ? one.cs[0] : -7.0;
        EXPECT_EQ(all.p[i], p) << "point " << i;
        EXPECT_EQ(all.cs[i], cs) << "point " << i;
        EXPECT_EQ(listed.p[i], p) << "point " << i << " (listed)";
        EXPECT_EQ(listed.cs[i], cs) << "point " << i << " (listed)";
    }
    // The rules were exercised: tension kept, tension cut, the cut-off's zero pressure.
    EXPECT_LT(all.p[6], 0.0);
    EXPECT_EQ(all.p[2], 0.0);
    EXPECT_EQ(all.p[3], 0.0);
}
