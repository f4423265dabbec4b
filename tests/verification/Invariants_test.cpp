// Designed invariants of the SPH solver, checked bitwise where they are exact by design:
//  * the dormant-region skipping changes nothing (a particle it skips has exactly zero rates);
//  * 1 and 2 threads give identical results (fixed neighbour order, per-particle gathers);
//  * mass is exact (particles carry fixed masses);
// and conservation within tolerances: total z-momentum (every axial force is a pair force,
// antisymmetric, mirror pairs included, except the area-weighted axial sums of the particles
// next to the axis) and total energy (compatible energy equation; leapfrog truncation error
// and the unbooked work of those axial sums). And the count of what time-step bins would
// evaluate covers every evaluated particle and element, with each element's own vote.
#include "SceneRun.hpp"
#include "Tolerance.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <limits>
#include <omp.h>

using namespace hvi;
using nlohmann::json;

namespace {

/// A small Al sphere on a thick Al plate at 2 km/s, axisymmetric, with strength: nothing is
/// deleted in 0.3 us, and most of the plate is still dormant.
json impactScene(double spacing, const std::string& geometry = "axisymmetric",
                 const std::string& energyUpdate = "trapezoid") {
    return {{"geometry", geometry},
            {"sph", {{"particle_spacing_mm", spacing}, {"energy_update", energyUpdate}}},
            {"run", {{"end_time_us", 0.3}, {"stop_debris_speed_km_s", 0.0},
                     {"stop_no_new_penetration_us", 0.0}}},
            {"domain", {{"radius_mm", 11.0}}},
            {"bodies",
             {{{"name", "sphere"}, {"role", "projectile"}, {"material", "Al6061-T6"},
               {"shape", {{"type", "sphere"}, {"center_z_mm", -0.5 - spacing},
                          {"radius_mm", 0.5}}},
               {"velocity", {{"z_km_s", 2.0}}}},
              {{"name", "plate"}, {"role", "bumper"}, {"material", "Al6061-T6"},
               {"shape", {{"type", "plate"}, {"z_front_mm", 0.0}, {"thickness_mm", 1.5},
                          {"outer_radius_mm", 10.0}}}}}}};
}

struct Outcome {
    std::vector<double> z, r, vz, e;
    double momentumDrift = 0.0, maxEnergyError = 0.0, massDrift = 0.0;
    std::size_t deleted = 0;
    double activeFraction = 1.0;
    std::size_t maxActive = 0;
};

Outcome run(double spacing, bool skipDormant, int threads,
            const std::string& geometry = "axisymmetric",
            const std::string& energyUpdate = "trapezoid") {
    omp_set_num_threads(threads);
    const auto scene = test::makeScene(impactScene(spacing, geometry, energyUpdate));
    solver::SimulationOptions options;
    options.skipDormant = skipDormant;
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"), options);
    const auto t0 = sim.totals();
    Outcome out;
    double activeSum = 0.0;
    long steps = 0;
    test::runUntil(sim, 0.3, [&](const solver::Simulation& s) {
        out.maxEnergyError = std::max(out.maxEnergyError, std::fabs(s.energyError()));
        activeSum += static_cast<double>(s.activeCount()) / static_cast<double>(s.aliveCount());
        out.maxActive = std::max(out.maxActive, s.activeCount());
        ++steps;
    });
    const auto t1 = sim.totals();
    out.momentumDrift = std::fabs(t1.momentumZ - t0.momentumZ) / std::fabs(t0.momentumZ);
    out.massDrift = std::fabs(t1.mass + t1.deletedMass - t0.mass) / t0.mass;
    out.deleted = t1.deleted;
    out.activeFraction = activeSum / static_cast<double>(steps);
    const auto& ps = sim.particles();
    out.z = ps.z;
    out.r = ps.r;
    out.vz = ps.vz;
    out.e = ps.e;
    return out;
}

} // namespace

TEST(Invariants, DormantSkippingIsExact) {
    const Outcome skip = run(0.05, true, 1);
    const Outcome full = run(0.05, false, 1);
    std::printf("mean active fraction with skipping: %.2f\n", skip.activeFraction);
    EXPECT_LT(skip.activeFraction, 0.9) << "the test must exercise the skipping";
    EXPECT_EQ(skip.z, full.z);
    EXPECT_EQ(skip.r, full.r);
    EXPECT_EQ(skip.vz, full.vz);
    EXPECT_EQ(skip.e, full.e);
}

TEST(Invariants, OneAndTwoThreadsAgreeBitwise) {
    const Outcome one = run(0.05, true, 1);
    const Outcome two = run(0.05, true, 2);
    // Loops go parallel only above kParallelMinItems: the scene must get there.
    EXPECT_GT(two.maxActive, hvi::kParallelMinItems);
    EXPECT_EQ(one.z, two.z);
    EXPECT_EQ(one.vz, two.vz);
    EXPECT_EQ(one.e, two.e);
}

TEST(Invariants, ConservationWithoutDeletion) {
    const Outcome o = run(0.04, true, 1);
    std::printf("axisymmetric: z-momentum drift %.3e, max |energy error| %.3e, mass drift %.1e\n",
                o.momentumDrift, o.maxEnergyError, o.massDrift);
    ASSERT_EQ(o.deleted, 0u) << "the scene is meant to delete nothing";
    EXPECT_EQ(o.massDrift, 0.0); // fixed particle masses: exact
    // Energy: compatible update, so only the time integration error remains; the bar
    // for an elastic-plastic impact is 1 %.
    EXPECT_LT(o.maxEnergyError, 0.01);
    // z-momentum, axisymmetric: every axial force is a pair force (the hoop force is radial)
    // except next to the axis, where the axial sums are the area-weighted ones so that a flow
    // along z stays one-dimensional (sph/SphHydro.hpp; issue #24). Measured 4.0e-4 (round-off,
    // 2e-15, when the excess was handed on to the neighbours as pair forces). The bar still
    // fails a per-particle axial term of consequence (the former axial artifact removal
    // drifted 4.5e-3 here); issue #4's 1e-6 held only with the hand-on, which the flyer-plate
    // axis test fails.
    EXPECT_LT(o.momentumDrift, 1e-3);
}

TEST(Invariants, CompatibleEnergyUpdateIsExactPlanar) {
    // The half kicks pay each pair's work with their mean velocities (sph/PairWork.hpp):
    // every force is a pair force in planar mode, so kinetic plus internal energy is conserved
    // to round-off at any step, where the trapezoid update leaves the step's truncation error.
    const Outcome trapezoid = run(0.04, true, 1, "planar");
    const Outcome compatible = run(0.04, true, 1, "planar", "compatible");
    std::printf("planar: max |energy error| %.3e trapezoid, %.3e compatible\n",
                trapezoid.maxEnergyError, compatible.maxEnergyError);
    ASSERT_EQ(compatible.deleted, 0u);
    EXPECT_LT(compatible.maxEnergyError, 1e-11);
    EXPECT_GT(trapezoid.maxEnergyError, 1e3 * compatible.maxEnergyError);
}

TEST(Invariants, CompatibleEnergyUpdateAxisymmetric) {
    // Axisymmetric, the axial excess taken off next to the axis is not a pair force and its
    // work is not the one booked (sph/SphHydro.hpp): that, not the time integration, is this
    // scene's energy error (measured: 5.57e-4 trapezoid, 5.60e-4 compatible). The update keeps
    // the bar, and 1 and 2 threads still agree bitwise.
    const Outcome one = run(0.04, true, 1, "axisymmetric", "compatible");
    const Outcome two = run(0.04, true, 2, "axisymmetric", "compatible");
    std::printf("axisymmetric, compatible: max |energy error| %.3e\n", one.maxEnergyError);
    EXPECT_LT(one.maxEnergyError, 0.01);
    EXPECT_GT(two.maxActive, hvi::kParallelMinItems);
    EXPECT_EQ(one.z, two.z);
    EXPECT_EQ(one.vz, two.vz);
    EXPECT_EQ(one.e, two.e);
}

TEST(Invariants, PlanarMomentumIsExact) {
    // Planar mode has no hoop terms: every force is a pair force, antisymmetric to round-off.
    const Outcome o = run(0.04, true, 1, "planar");
    std::printf("planar: z-momentum drift %.3e, max |energy error| %.3e\n", o.momentumDrift,
                o.maxEnergyError);
    ASSERT_EQ(o.deleted, 0u);
    EXPECT_LT(o.momentumDrift, 1e-12);
    EXPECT_LT(o.maxEnergyError, 0.01);
}

namespace {

/// An FE Al block at 1 km/s hits a resting SPH Al plate (planar): the plate's particles are
/// dormant until contact pushes them, so the solver must advance particles that contact sets
/// moving even though no SPH evaluation has woken them yet. The elements are half the
/// particle spacing, so they set the time step throughout (dormant particles cast no vote, so
/// where they would set it the two runs would differ by design).
struct ContactOutcome {
    std::vector<double> z, vz, e, nodeZ, nodeVz;
    std::size_t contacts = 0;
    /// Points each package evaluated: before the first step, then after each step.
    std::vector<double> sphEvaluated, feEvaluated;
    /// The smallest element vote over the FE package's vote (>= 1: that vote also takes the
    /// undisturbed elements' step), the least over the steps.
    double feSmallestStepRatio = std::numeric_limits<double>::infinity();
    std::vector<double> feSmallestSteps; ///< the smallest element vote of each assembly [us]
    std::vector<std::pair<std::string, solver::BinnedWork>> binned;
};

ContactOutcome runContact(bool skipDormant) {
    omp_set_num_threads(1);
    const json doc = {
        {"geometry", "planar"},
        {"sph", {{"particle_spacing_mm", 0.025}}},
        {"fe", {{"element_size_mm", 0.0125}}},
        {"run", {{"end_time_us", 0.05}, {"stop_debris_speed_km_s", 0.0},
                 {"stop_no_new_penetration_us", 0.0}}},
        {"domain", {{"radius_mm", 10.0}}},
        {"bodies",
         {{{"name", "block"}, {"role", "projectile"}, {"material", "Al6061-T6"},
           {"discretization", "fe"},
           {"shape", {{"type", "rectangle"}, {"z_min_mm", -0.251}, {"z_max_mm", -0.001},
                      {"r_min_mm", 1.0}, {"r_max_mm", 2.0}}},
           {"velocity", {{"z_km_s", 1.0}}}},
          {{"name", "plate"}, {"role", "bumper"}, {"material", "Al6061-T6"},
           {"shape", {{"type", "rectangle"}, {"z_min_mm", 0.0}, {"z_max_mm", 0.5},
                      {"r_min_mm", 0.0}, {"r_max_mm", 3.0}}}}}}};
    const auto scene = test::makeScene(doc);
    solver::SimulationOptions options;
    options.skipDormant = skipDormant;
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"), options);
    ContactOutcome out;
    auto count = [&](const solver::Simulation& s) {
        out.sphEvaluated.push_back(static_cast<double>(s.activeCount()));
        // The elements of the last assembly (contact may admit more before the next update).
        const auto& steps = s.finiteElements()->elementSteps();
        out.feEvaluated.push_back(static_cast<double>(steps.size()));
        if (!steps.empty()) {
            const double smallest = *std::min_element(steps.begin(), steps.end());
            out.feSmallestStepRatio =
                std::min(out.feSmallestStepRatio, smallest / s.finiteElements()->stableTimeStep());
            out.feSmallestSteps.push_back(smallest);
        }
    };
    count(sim);
    test::runUntil(sim, 0.05, [&](const solver::Simulation& s) {
        out.contacts += s.contact()->contactCount();
        count(s);
    });
    out.binned = sim.binnedWork();
    out.z = sim.particles().z;
    out.vz = sim.particles().vz;
    out.e = sim.particles().e;
    out.nodeZ = sim.finiteElements()->nodes().z;
    out.nodeVz = sim.finiteElements()->nodes().vz;
    return out;
}

} // namespace

// Time-step bins' count (solver/BinnedWork.hpp): each step's vote counts the points of the
// evaluation before it, every one of them (the evaluation that ends the run casts no vote),
// and bins can only take fewer evaluations, not more.
TEST(Invariants, TimeBinsCountEveryEvaluatedPoint) {
    const ContactOutcome o = runContact(true);
    ASSERT_EQ(o.binned.size(), 2u);
    auto allButLast = [](const std::vector<double>& v) {
        double sum = 0.0;
        for (std::size_t k = 0; k + 1 < v.size(); ++k) {
            sum += v[k];
        }
        return sum;
    };
    for (const auto& [name, work] : o.binned) {
        const double expected = allButLast(name == "sph" ? o.sphEvaluated : o.feEvaluated);
        EXPECT_EQ(work.evaluated(), expected) << name;
        EXPECT_GT(work.fraction(), 0.0) << name;
        EXPECT_LE(work.fraction(), 1.0) << name;
        std::printf("%s: %.0f point-steps evaluated, %.1f with time bins (%.3f)\n", name.c_str(),
                    work.evaluated(), work.binned(), work.fraction());
    }
    EXPECT_EQ(o.binned[0].first, "sph");
    EXPECT_EQ(o.binned[1].first, "fe");
    // The elements' own votes are the ones the package's vote is the smallest of, and they
    // are each assembly's: the impact compresses the block's front elements, whose votes fall
    // below the undisturbed elements' of the first assembly.
    EXPECT_GE(o.feSmallestStepRatio, 1.0);
    EXPECT_LT(o.feSmallestStepRatio, 1.0 + 1e-12);
    ASSERT_FALSE(o.feSmallestSteps.empty());
    const double first = o.feSmallestSteps.front();
    const double least = *std::min_element(o.feSmallestSteps.begin(), o.feSmallestSteps.end());
    EXPECT_LT(least, 0.99 * first) << "first " << first << " us, least " << least << " us";
}

TEST(Invariants, DormantSkippingIsExactThroughContact) {
    const ContactOutcome skip = runContact(true);
    const ContactOutcome full = runContact(false);
    ASSERT_GT(skip.contacts, 0u) << "the block must reach the plate";
    EXPECT_EQ(skip.z, full.z);
    EXPECT_EQ(skip.vz, full.vz);
    EXPECT_EQ(skip.e, full.e);
    EXPECT_EQ(skip.nodeZ, full.nodeZ);
    EXPECT_EQ(skip.nodeVz, full.nodeVz);
}
