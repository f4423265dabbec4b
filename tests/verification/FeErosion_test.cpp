// Erosion (issue #5, item 3): an SPH Al sphere (1 mm diameter) striking an FE Al 6061-T6 plate
// (1 mm thick, erosion factor 1.5) perforates it above a speed and not below it. The
// threshold was bracketed once with this test's own scene (docs/notebook/fe-erosion.md gives
// the sweep: between 1.5 and 1.6 km/s); the test checks 1.0 km/s (not perforated, well below)
// and 2.2 km/s (perforated, well above), that eroded mass is reported, and that the energy
// error stays below 5 %.
#include "SceneRun.hpp"
#include "Tolerance.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

namespace {

constexpr double kEndTime = 6.0; ///< [us]

struct Outcome {
    bool perforated = false;
    std::size_t eroded = 0;
    double erodedMassMg = 0.0;
    double maxEnergyError = 0.0;
    double time = 0.0;
    std::string stopReason;
    double momentumDrift = 0.0;     ///< max |p_z + p_z,deleted - p_z,0| / p_z,0 [-]
    std::size_t freeNodes = 0;      ///< alive nodes with no alive element at the end
    std::size_t plateParticles = 0; ///< particles made of eroded plate elements
};

Outcome strike(double speed, double spacing) {
    const double radius = 0.5;
    json doc = {
        {"geometry", "axisymmetric"},
        {"sph", {{"particle_spacing_mm", spacing}}},
        {"fe", {{"element_size_mm", spacing}, {"erosion_factor", 1.5}}},
        {"run", {{"end_time_us", kEndTime}, {"stop_debris_speed_km_s", 0.0},
                 {"stop_no_new_penetration_us", 0.0}}},
        {"domain", {{"radius_mm", 6.5}}},
        {"bodies",
         {{{"name", "projectile"}, {"role", "projectile"}, {"material", "Al6061-T6"},
           {"shape", {{"type", "sphere"}, {"center_z_mm", -(radius + spacing)},
                      {"radius_mm", radius}}},
           {"velocity", {{"z_km_s", speed}}}},
          {{"name", "plate"}, {"role", "bumper"}, {"material", "Al6061-T6"},
           {"discretization", "fe"},
           {"shape", {{"type", "plate"}, {"z_front_mm", 0.0}, {"thickness_mm", 1.0},
                      {"outer_radius_mm", 6.0}}}}}}};
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    Outcome out;
    const double p0 = sim.totals().momentumZ;
    test::runUntil(sim, kEndTime, [&](const solver::Simulation& s) {
        if (s.step() % 10 == 0) {
            out.maxEnergyError = std::max(out.maxEnergyError, std::fabs(s.energyError()));
            const auto t = s.totals();
            out.momentumDrift = std::max(
                out.momentumDrift, std::fabs(t.momentumZ + t.deletedMomentumZ - p0) / p0);
        }
    });
    const auto& nd = sim.finiteElements()->nodes();
    for (std::size_t n = 0; n < nd.size(); ++n) {
        out.freeNodes += nd.alive[n] && nd.elementCount[n] == 0 ? 1 : 0;
    }
    const auto& ps = sim.particles();
    for (std::size_t i = 0; i < ps.size(); ++i) {
        out.plateParticles += ps.body[i] == 1 && ps.mass[i] > 0.0 ? 1 : 0;
    }
    out.maxEnergyError = std::max(out.maxEnergyError, std::fabs(sim.energyError()));
    // Perforated: a column of the structured mesh (element iz * nr + ir, z outer) eroded
    // through the whole thickness, i.e. a hole from the front face to the rear face.
    const auto& el = sim.finiteElements()->elements();
    const std::size_t nr = 150, nz = 25; // 6 mm / 0.04 mm, 1 mm / 0.04 mm
    EXPECT_EQ(el.size(), nr * nz);
    for (std::size_t ir = 0; ir < nr && !out.perforated; ++ir) {
        bool open = true;
        for (std::size_t iz = 0; iz < nz && open; ++iz) {
            open = !el.alive[iz * nr + ir];
        }
        out.perforated = open;
    }
    for (std::size_t i = 0; i < el.size(); ++i) {
        if (!el.alive[i]) {
            ++out.eroded;
            out.erodedMassMg += el.mass[i];
        }
    }
    out.time = sim.time();
    out.stopReason = sim.stopReason().value_or("running");
    const auto t = sim.totals();
    std::printf("%.2f km/s, spacing %.3f mm: %s at %.3f us (%s), %zu elements eroded (%.4f mg), "
                "max |energy error| %.2e (final %+.2e; contact heat %.2e, deleted and eroded "
                "%.2e of E0); momentum drift %.1e; %zu particles made of eroded elements, "
                "%zu free nodes; deleted %zu runaway, %zu out of domain\n",
                speed, spacing, out.perforated ? "perforated" : "not perforated", out.time,
                out.stopReason.c_str(), out.eroded, out.erodedMassMg, out.maxEnergyError,
                sim.energyError(), sim.contact()->dissipatedEnergy() / sim.initialEnergy(),
                t.deletedEnergy / sim.initialEnergy(), out.momentumDrift, out.plateParticles,
                out.freeNodes, sim.runawayDeleted(), sim.outOfDomainDeleted());
    return out;
}

} // namespace

TEST(FeErosion, Sweep) {
    const char* list = std::getenv("HVI_EROSION_SWEEP");
    if (!list) {
        GTEST_SKIP() << "set HVI_EROSION_SWEEP=\"v1 v2 ...\" to bracket the threshold";
    }
    char* end = nullptr;
    for (double v = std::strtod(list, &end); end && end != list; v = std::strtod(list, &end)) {
        strike(v, 0.04);
        list = end;
    }
}

// The sweep at 0.04 mm (docs/notebook/fe-erosion.md) put the threshold between 1.5 km/s (not
// perforated at 6 us) and 1.6 km/s (perforated); the test checks 1.0 and 2.2 km/s, about a
// third either side.
TEST(FeErosion, NotPerforatedWellBelowThreshold) {
    const Outcome o = strike(1.0, 0.04);
    EXPECT_FALSE(o.perforated);
    EXPECT_GT(o.eroded, 0U) << "the crater erodes some elements";
    EXPECT_GT(o.erodedMassMg, 0.0);
    EXPECT_LT(o.maxEnergyError, 0.05);
}

TEST(FeErosion, PerforatedWellAboveThreshold) {
    const Outcome o = strike(2.2, 0.04);
    EXPECT_TRUE(o.perforated);
    EXPECT_GT(o.erodedMassMg, 0.0);
    EXPECT_LT(o.maxEnergyError, 0.05);
    // Every eroded element became a particle (fe.eroded_material "particles", the default),
    // so no free node is left. The conversion itself conserves momentum exactly
    // (unit/solver/ErodedParticles_test.cpp). The ledger's z-momentum (alive + deleted) drifts
    // only through the SPH particles next to the axis, whose axial sums are the area-weighted
    // ones (sph/SphHydro.hpp): measured 1.3e-3 here, at 1.0 and at 2.2 km/s alike; round-off
    // before that change. The bar still fails a conversion that lost the eroded material's
    // momentum (5.0 mg of plate material moving with the debris, against the sphere's 1.41 mg
    // at 2.2 km/s).
    EXPECT_EQ(o.plateParticles, o.eroded);
    EXPECT_EQ(o.freeNodes, 0U);
    EXPECT_LT(o.momentumDrift, 3e-3);
}
