// Designed invariants of the finite-element package, checked bitwise where they are exact by
// design:
//  * skipping dormant elements changes nothing (an element whose nodes never moved and whose
//    material is in its reference state has exactly zero rates and forces; one that woke
//    stays evaluated);
//  * 1 and 2 threads give identical results (per-element updates, per-node gathers of the
//    corner forces in a fixed element order).
// The scene has more awake elements than the threading threshold, erosion (eroded elements
// become particles) and contact, so every FE loop runs threaded and every path is covered.
#include "SceneRun.hpp"
#include "SyntheticRun.hpp"
#include "core/Parallel.hpp"

#include <gtest/gtest.h>
#include <omp.h>

using namespace hvi;
using nlohmann::json;

namespace {

/// A 1 mm Al sphere (SPH) at 3 km/s on a 0.5 mm Al FE plate of 8 mm radius, 0.02 mm.
json plateScene() {
    json plate = test::plateBody("plate", "bumper", 0.0, 0.5, 8.0);
    plate["discretization"] = "fe";
    return {{"geometry", "axisymmetric"},
            {"sph", {{"particle_spacing_mm", 0.02}}},
            {"fe", {{"element_size_mm", 0.02}}},
            {"run",
             {{"end_time_us", 10.0},
              {"stop_debris_speed_km_s", 0.0},
              {"stop_no_new_penetration_us", 0.0}}},
            {"domain", {{"radius_mm", 8.5}}},
            {"bodies", {test::projectileBody(0.5, 3.0), plate}}};
}

struct Outcome {
    std::vector<double> particleZ, particleVz, nodeZ, nodeVr, elementE, elementDamage;
    std::vector<uint8_t> alive;
    std::size_t eroded = 0, maxEvaluated = 0, elements = 0;
    double time = 0.0;
};

Outcome run(bool skipDormant, int threads) {
    omp_set_num_threads(threads);
    solver::SimulationOptions options;
    options.skipDormant = skipDormant;
    solver::Simulation sim(test::makeScene(plateScene()),
                           scene::sceneLibrary(json::object(), "<test>"), options);
    Outcome out;
    for (int k = 0; k < 400; ++k) {
        sim.advance();
        out.maxEvaluated = std::max(out.maxEvaluated, sim.finiteElements()->evaluatedCount());
    }
    omp_set_num_threads(1);
    const auto& fe = *sim.finiteElements();
    out.particleZ = sim.particles().z;
    out.particleVz = sim.particles().vz;
    out.nodeZ = fe.nodes().z;
    out.nodeVr = fe.nodes().vr;
    out.elementE = fe.elements().e;
    out.elementDamage = fe.elements().damage;
    out.alive = fe.elements().alive;
    out.eroded = fe.erodedCount();
    out.elements = fe.elements().size();
    out.time = sim.time();
    return out;
}

void expectIdentical(const Outcome& a, const Outcome& b) {
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.eroded, b.eroded);
    EXPECT_EQ(a.alive, b.alive);
    EXPECT_EQ(a.particleZ, b.particleZ);
    EXPECT_EQ(a.particleVz, b.particleVz);
    EXPECT_EQ(a.nodeZ, b.nodeZ);
    EXPECT_EQ(a.nodeVr, b.nodeVr);
    EXPECT_EQ(a.elementE, b.elementE);
    EXPECT_EQ(a.elementDamage, b.elementDamage);
}

} // namespace

TEST(FeInvariants, DormantSkippingIsExactAndOneAndTwoThreadsAgree) {
    const Outcome skipped = run(true, 1);
    // The test covers what it claims: erosion happened, part of the plate stayed dormant, and
    // the awake elements outnumber the threading threshold.
    ASSERT_GT(skipped.eroded, 0U);
    ASSERT_LT(skipped.maxEvaluated, skipped.elements);
    ASSERT_GT(skipped.maxEvaluated, kParallelMinItems);
    {
        SCOPED_TRACE("every element evaluated, one thread");
        expectIdentical(skipped, run(false, 1));
    }
    {
        SCOPED_TRACE("dormant elements skipped, two threads");
        expectIdentical(skipped, run(true, 2));
    }
}
