// A longitudinal elastic wave in an Al bar (issue #4, item 3): a slow flyer (0.02 km/s, well
// below yield; touching the bar at t = 0, since at this speed closing even one particle
// spacing would take a microsecond)
// sigma ~ rho c_L u = 0.17 GPa < Y = 0.29 GPa, launches a plane wave into a wide
// bar in planar (plane-strain) mode, so the wave is one of uniaxial strain and travels at
// c_L = sqrt(c0^2 + 4G/(3 rho0)) (bulk sound speed of the EOS plus the shear modulus of the
// library: 6.408 km/s). The front is tracked at two times on the centre line, where the
// release waves from the bar's sides have not arrived; 2 % tolerance (issue #4). The energy
// error stays below 1 % (issue #4, item 4).
#include "SceneRun.hpp"
#include "Tolerance.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

namespace {

/// The wave front: where vz falls through half the particle velocity at the leading edge of
/// the pulse, along the centre band (x in [1, 2] mm).
double frontPosition(const sph::ParticleSet& ps, double halfVelocity) {
    const double bin = 0.025;
    std::vector<double> sum(400, 0.0);
    std::vector<int> count(400, 0);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.body[i] != 1 || ps.r[i] < 1.0 || ps.r[i] > 2.0) {
            continue;
        }
        const auto b = static_cast<std::size_t>(ps.z[i] / bin);
        if (b < sum.size()) {
            sum[b] += ps.vz[i];
            ++count[b];
        }
    }
    // Scan from downstream: the front is the furthest point the pulse has reached (behind the
    // pulse, once the flyer's rear-surface release arrives, the bar is at rest again).
    for (std::size_t b = sum.size() - 1; b >= 1; --b) {
        if (count[b - 1] > 0 && count[b] > 0 && sum[b - 1] / count[b - 1] >= halfVelocity) {
            const double v0 = sum[b - 1] / count[b - 1], v1 = sum[b] / count[b];
            const double z0 = (static_cast<double>(b) - 0.5) * bin;
            return z0 + bin * (v0 - halfVelocity) / (v0 - v1);
        }
    }
    return NAN;
}

} // namespace

TEST(ElasticWave, LongitudinalSpeedInAluminium) {
    const double spacing = 0.025, flyerSpeed = 0.02;
    json doc = {{"geometry", "planar"},
                {"sph", {{"particle_spacing_mm", spacing}}},
                {"run", {{"end_time_us", 0.5}, {"stop_debris_speed_km_s", 0.0},
                         {"stop_no_new_penetration_us", 0.0}}},
                {"domain", {{"radius_mm", 10.0}}},
                {"bodies",
                 {{{"name", "flyer"}, {"material", "Al6061-T6"},
                   {"shape", {{"type", "rectangle"}, {"z_min_mm", -0.5},
                              {"z_max_mm", 0.0}, {"r_min_mm", 0.0}, {"r_max_mm", 3.0}}},
                   {"velocity", {{"z_km_s", flyerSpeed}}}},
                  {{"name", "bar"}, {"material", "Al6061-T6"},
                   {"shape", {{"type", "rectangle"}, {"z_min_mm", 0.0}, {"z_max_mm", 4.0},
                              {"r_min_mm", 0.0}, {"r_max_mm", 3.0}}}}}}};
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    double maxEnergyError = 0.0, yieldedStrain = 0.0;
    auto track = [&](const solver::Simulation& s) {
        maxEnergyError = std::max(maxEnergyError, std::fabs(s.energyError()));
    };
    const double half = 0.25 * flyerSpeed; // u_p = v/2 for like materials; half of it
    const double t1 = 0.25, t2 = 0.5;
    test::runUntil(sim, t1, track);
    const double z1 = frontPosition(sim.particles(), half);
    const double time1 = sim.time();
    test::runUntil(sim, t2, track);
    const double z2 = frontPosition(sim.particles(), half);
    for (double eps : sim.particles().plasticStrain) {
        yieldedStrain = std::max(yieldedStrain, eps);
    }
    const double speed = (z2 - z1) / (sim.time() - time1);
    const double rho0 = 2.703, c0 = 5.24, shear = 27.6;
    const double cL = std::sqrt(c0 * c0 + 4.0 * shear / (3.0 * rho0));
    std::printf("elastic wave: front %.4f -> %.4f mm, speed %.4f km/s (c_L %.4f), max energy "
                "error %.2e, max plastic strain %.1e\n",
                z1, z2, speed, cL, maxEnergyError, yieldedStrain);
    EXPECT_EQ(yieldedStrain, 0.0) << "the wave must stay elastic";
    EXPECT_TRUE(test::near("wave speed [km/s]", speed, cL, 0.0, 0.02));
    EXPECT_LT(maxEnergyError, 0.01);
}
