// The erosion rule of FeSolid.hpp for failure: an element with Johnson-Cook damage 1 that is
// still compact keeps its pressure and stays; once it has expanded below the stress cut-off
// density (sph.min_density_ratio x rho0) it carries nothing and is removed. The expansion
// here is nearly isotropic in the plane, so its geometric strain (about 0.2) stays far below
// the erosion factor: only the failure rule can remove it.
#include "SceneRun.hpp"

#include <array>
#include <cmath>
#include <gtest/gtest.h>

using namespace hvi;
using nlohmann::json;

namespace {

constexpr double kSize = 0.04;

/// A resting 0.2 mm x 0.2 mm FE Al block (planar, 5 x 5 elements) whose centre element has
/// failed (D = 1) and whose four nodes move away from (outward) or towards (inward) its
/// centroid at `speed` [km/s]. Returns the centre element's alive flag after `time` [us] and
/// its lowest density on the way.
struct Outcome {
    bool alive = true;
    double minDensityRatio = 1.0;
    double geometricStrain = 0.0;
};

Outcome run(double speed, double time) {
    const json doc = {{"geometry", "planar"},
                      {"sph", {{"particle_spacing_mm", kSize}, {"min_density_ratio", 0.5}}},
                      {"fe", {{"element_size_mm", kSize}, {"erosion_factor", 1.5}}},
                      {"run", {{"end_time_us", time}, {"stop_debris_speed_km_s", 0.0},
                               {"stop_no_new_penetration_us", 0.0}}},
                      {"domain", {{"radius_mm", 5.0}}},
                      {"bodies",
                       {{{"name", "block"}, {"role", "bumper"}, {"material", "Al6061-T6"},
                         {"discretization", "fe"},
                         {"shape", {{"type", "rectangle"}, {"z_min_mm", 0.0}, {"z_max_mm", 0.2},
                                    {"r_min_mm", 1.0}, {"r_max_mm", 1.2}}}}}}};
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    auto& fe = *sim.finiteElements();
    auto& el = fe.elements();
    auto& nd = fe.nodes();
    // The element whose centroid is nearest the block's centre.
    std::size_t centre = 0;
    double best = 1e300;
    std::array<double, 2> mid{};
    for (std::size_t e = 0; e < el.size(); ++e) {
        double z = 0.0, r = 0.0;
        for (int k = 0; k < 4; ++k) {
            const auto n = static_cast<std::size_t>(el.connectivity[4 * e + static_cast<std::size_t>(k)]);
            z += 0.25 * nd.z[n];
            r += 0.25 * nd.r[n];
        }
        const double d = std::hypot(z - 0.1, r - 1.1);
        if (d < best) {
            best = d;
            centre = e;
            mid = {z, r};
        }
    }
    el.damage[centre] = 1.0;
    for (int k = 0; k < 4; ++k) {
        const auto n = static_cast<std::size_t>(el.connectivity[4 * centre + static_cast<std::size_t>(k)]);
        const double dz = nd.z[n] - mid[0], dr = nd.r[n] - mid[1];
        const double len = std::hypot(dz, dr);
        nd.vz[n] = speed * dz / len;
        nd.vr[n] = speed * dr / len;
    }
    const double rho0 = el.rho[centre];
    Outcome out;
    test::runUntil(sim, time, [&](const solver::Simulation&) {
        if (el.alive[centre]) {
            out.minDensityRatio = std::min(out.minDensityRatio, el.rho[centre] / rho0);
            out.geometricStrain = sim.finiteElements()->erosionStrain()[centre];
        }
    });
    out.alive = el.alive[centre] != 0;
    return out;
}

} // namespace

TEST(ErosionRule, FailedCompactElementStays) {
    // Squeezed at 0.05 km/s for 0.02 us: compact, failed, carrying pressure.
    const Outcome o = run(-0.05, 0.02);
    EXPECT_TRUE(o.alive) << "a failed element that is still compact must not erode";
    EXPECT_GT(o.minDensityRatio, 0.5);
}

TEST(ErosionRule, FailedExpandedElementErodes) {
    // Torn apart at 2 km/s: its area doubles in about 0.005 us.
    const Outcome o = run(2.0, 0.03);
    std::printf("lowest density before erosion %.3f rho0, geometric strain %.3f\n",
                o.minDensityRatio, o.geometricStrain);
    EXPECT_FALSE(o.alive) << "a failed element expanded below the cut-off must erode";
    EXPECT_LT(o.geometricStrain, 1.5) << "the erosion must come from the failure rule";
}
