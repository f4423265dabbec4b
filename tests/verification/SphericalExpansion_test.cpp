// A hot sphere expanding into vacuum stays a sphere: an invariant of the axisymmetric
// formulation near the axis. In (z, r) a sphere's material is spread over rings, those near
// the axis holding a tiny mass, and the pressure force reaches them through the radius
// weighting, the hoop terms and the axis ghosts (docs/formulation.md). Spherical symmetry
// gives two exact statements for the mass distribution at any time:
//   <z^2> = <x^2> = <r^2> / 2 (mass-weighted, centre at the origin), and
//   the mass within 30 degrees of the axis (both polar caps) is 1 - cos 30 = 13.40 % of the total.
// A formulation that pushes material off the axis (or holds it there) breaks both.
//
// Measured (0.01 mm spacing, 3 930 particles, 0.45 us, the sphere's radius roughly doubled):
// ideal gas (gamma 5/3, e0 1 MJ/kg): ratio 1.0101, caps 13.73 %; Al 6061-T6 (Mie-Grueneisen,
// strength and failure, e0 5 MJ/kg): ratio 1.0028, caps 13.21 % (1.0095, 13.69 % and 1.0009,
// 13.16 % with the former radius-weighted pair weight). The lattice itself starts at
// 0.9985 and 13.42 %. Bars: 2 % on the ratio and 0.6 percentage points on the caps, twice the
// largest deviation measured. Checked by breaking the code: without the hoop force the ratio
// reaches 1.48 (gas) and 2.51 (Al) and the caps 29.7 % and 24.0 %.
#include "SceneRun.hpp"
#include "Tolerance.hpp"
#include "core/Units.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>

using namespace hvi;
using nlohmann::json;

namespace {

struct Shape {
    double ratio = 0.0;      ///< <z^2> / (<r^2>/2)
    double capShare = 0.0;   ///< mass share within 30 degrees of the axis
    double meanSquare = 0.0; ///< <z^2 + r^2> [mm^2]
};

Shape measure(const sph::ParticleSet& ps) {
    double m = 0.0, z2 = 0.0, r2 = 0.0, cap = 0.0;
    const double cos30 = std::cos(units::kPi / 6.0);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        m += ps.mass[i];
        z2 += ps.mass[i] * ps.z[i] * ps.z[i];
        r2 += ps.mass[i] * ps.r[i] * ps.r[i];
        if (std::fabs(ps.z[i]) > std::hypot(ps.z[i], ps.r[i]) * cos30) {
            cap += ps.mass[i];
        }
    }
    return {z2 / (0.5 * r2), cap / m, (z2 + r2) / m};
}

/// A 0.5 mm sphere of `material` centred at the origin, at rest, with internal energy e0
/// [MJ/kg], run to tEnd [us].
Shape expand(const std::string& material, double e0, double tEnd, Shape* initial) {
    json doc = {{"geometry", "axisymmetric"},
                {"sph",
                 {{"particle_spacing_mm", 0.01},
                  {"min_density_ratio", 0.001},
                  {"runaway_speed_factor", 1.0e5}}},
                {"run",
                 {{"end_time_us", tEnd},
                  {"stop_debris_speed_km_s", 0.0},
                  {"stop_no_new_penetration_us", 0.0}}},
                {"domain", {{"radius_mm", 20.0}, {"z_min_mm", -20.0}, {"z_max_mm", 20.0}}},
                // A tiny drift keeps the runaway rule's reference speed finite (1e5 x 1e-3 km/s);
                // it moves the centre by 5e-4 mm, far below the spacing.
                {"bodies",
                 {{{"name", "ball"},
                   {"role", "projectile"},
                   {"material", material},
                   {"shape", {{"type", "sphere"}, {"center_z_mm", 0.0}, {"radius_mm", 0.5}}},
                   {"velocity", {{"z_km_s", 1.0e-3}}}}}}};
    const auto scene = test::makeScene(doc);
    solver::Simulation sim(scene, scene::sceneLibrary(json::object(), "<test>"));
    auto& ps = sim.particles();
    for (std::size_t i = 0; i < ps.size(); ++i) {
        ps.e[i] = e0;
    }
    sim.refreshRates();
    *initial = measure(ps);
    test::runUntil(sim, tEnd);
    EXPECT_NEAR(sim.time(), tEnd, 1e-9);
    return measure(ps);
}

void expectSpherical(const char* label, const Shape& start, const Shape& end) {
    std::printf("%s: <z2>/(<r2>/2) %.4f (start %.4f), caps %.4f (start %.4f, sphere %.4f), "
                "<x2> grew %.2fx\n",
                label, end.ratio, start.ratio, end.capShare, start.capShare,
                1.0 - std::cos(units::kPi / 6.0), end.meanSquare / start.meanSquare);
    EXPECT_GT(end.meanSquare, 2.0 * start.meanSquare) << "the sphere must have expanded";
    EXPECT_TRUE(test::near("<z^2> / (<r^2>/2)", end.ratio, 1.0, 0.0, 0.02));
    EXPECT_TRUE(test::near("mass share within 30 degrees of the axis", end.capShare,
                           1.0 - std::cos(units::kPi / 6.0), 0.006, 0.0));
}

} // namespace

TEST(SphericalExpansion, IdealGasSphereStaysSpherical) {
    Shape start;
    const Shape end = expand("ideal_gas_5_3", 1.0, 0.45, &start);
    expectSpherical("ideal gas", start, end);
}

TEST(SphericalExpansion, HotAluminiumSphereStaysSpherical) {
    Shape start;
    const Shape end = expand("Al6061-T6", 5.0, 0.45, &start);
    expectSpherical("Al 6061-T6", start, end);
}
