// The instantaneous erosion strain (fe/ErosionStrain.hpp) against closed forms: zero for
// rigid motions and for pure volume change, (2/3) |ln lambda| for a stretch lambda along one
// in-plane direction, |gamma| / sqrt(3) to first order in a small simple shear gamma, and the
// hoop stretch of a ring moved outwards; +inf for an inverted element; the cheap bound that
// skips the logarithms never clears an element at its erosion limit. And in an FE run: an
// element driven to and fro (elastic ringing) keeps an instantaneous strain of the size of
// its amplitude, while the incremental measure grows with every cycle.
#include "SceneRun.hpp"
#include "Tolerance.hpp"
#include "fe/ErosionStrain.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <random>
#include <string>

using namespace hvi;
using fe::QuadState;

namespace {

/// A unit square element at radius r0 (corners counter-clockwise in (z, r)).
QuadState square(double r0) {
    QuadState q;
    q.z = {0.0, 1.0, 1.0, 0.0};
    q.r = {r0, r0, r0 + 1.0, r0 + 1.0};
    return q;
}

/// The square's corners mapped by x = F X + t (in-plane, about its first corner).
QuadState mapped(const QuadState& ref, double fzz, double fzr, double frz, double frr, double tz,
                 double tr) {
    QuadState q = ref;
    for (std::size_t a = 0; a < 4; ++a) {
        const double dz = ref.z[a] - ref.z[0], dr = ref.r[a] - ref.r[0];
        q.z[a] = ref.z[0] + tz + fzz * dz + fzr * dr;
        q.r[a] = ref.r[0] + tr + frz * dz + frr * dr;
    }
    return q;
}

} // namespace

TEST(ErosionStrain, RigidMotionAndVolumeChangeGiveZero) {
    const QuadState ref = square(2.0);
    const auto shape = fe::referenceShape(ref);
    const double c = std::cos(0.7), s = std::sin(0.7);
    // Planar: a rotation and a translation.
    EXPECT_NEAR(fe::instantaneousStrain(mapped(ref, c, -s, s, c, 3.0, -1.0), shape, false), 0.0,
                1e-14);
    // Axisymmetric: scaling the ring by 1.3 about the origin stretches it equally in z, r and
    // the hoop direction, a pure volume change.
    EXPECT_NEAR(
        fe::instantaneousStrain(mapped(ref, 1.3, 0.0, 0.0, 1.3, 0.0, 0.3 * ref.r[0]), shape, true),
        0.0, 1e-14);
}

TEST(ErosionStrain, UniaxialStretchAndSimpleShear) {
    const QuadState ref = square(2.0);
    const auto shape = fe::referenceShape(ref);
    for (const double lambda : {0.5, 0.9, 1.1, 2.0}) {
        const double expected = (2.0 / 3.0) * std::fabs(std::log(lambda));
        const double got =
            fe::instantaneousStrain(mapped(ref, lambda, 0.0, 0.0, 1.0, 0.0, 0.0), shape, false);
        EXPECT_TRUE(
            test::near("strain at lambda " + std::to_string(lambda), got, expected, 1e-14, 1e-12));
    }
    // Simple shear z += gamma r: the Hencky strain's equivalent is |gamma| / sqrt(3) to first
    // order (principal stretches exp(+-gamma/2)); the second-order term is below gamma^3.
    const double gamma = 1e-3;
    const double got =
        fe::instantaneousStrain(mapped(ref, 1.0, gamma, 0.0, 1.0, 0.0, 0.0), shape, false);
    EXPECT_TRUE(test::near("simple shear", got, gamma / std::sqrt(3.0), 0.0, 1e-6));
}

TEST(ErosionStrain, HoopStretchOfARingMovedOutwards) {
    // Axisymmetric: the element translated from r = 2 to r = 3 without changing its shape
    // keeps its in-plane shape but its ring is stretched by 3.5 / 2.5 (mean corner radii).
    const QuadState ref = square(2.0);
    const auto shape = fe::referenceShape(ref);
    const double lt = std::log(3.5 / 2.5);
    const double expected = (2.0 / 3.0) * lt; // e = (0, 0, ln lambda_theta)
    const double got =
        fe::instantaneousStrain(mapped(ref, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0), shape, true);
    EXPECT_TRUE(test::near("hoop stretch", got, expected, 1e-14, 1e-12));
}

TEST(ErosionStrain, InvertedElementIsInfinite) {
    const QuadState ref = square(2.0);
    const auto shape = fe::referenceShape(ref);
    EXPECT_TRUE(std::isinf(
        fe::instantaneousStrain(mapped(ref, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0), shape, false)));
}

TEST(ErosionStrain, CheapBoundNeverHidesAnErosion) {
    // strainCertainlyBelow() lets the update skip the logarithms. Over random deformations
    // (stretches up to e^{+-2}, rotations, shears, hoop stretches, inversions) it must never
    // clear an element whose strain reaches the limit, and must clear every element more
    // than ln(4)/3 below it (the bound's documented slack), or it would save nothing.
    const QuadState ref = square(2.0);
    const auto shape = fe::referenceShape(ref);
    std::mt19937_64 random(20261123);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double slack = std::log(4.0) / 3.0;
    int cleared = 0, evaluated = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const double l1 = std::exp(2.0 * unit(random)), l2 = std::exp(2.0 * unit(random));
        const double angle = 3.2 * unit(random), shear = unit(random);
        const double c = std::cos(angle), sn = std::sin(angle);
        // F = R(angle) diag(l1, l2) + shear e_z (x) e_r, sometimes inverted (l1 < 0).
        const double sign = trial % 50 == 0 ? -1.0 : 1.0;
        const double fzz = c * sign * l1, fzr = -sn * l2 + shear, frz = sn * sign * l1,
                     frr = c * l2;
        const double tr = 0.5 * ref.r[0] * unit(random);
        const QuadState q = mapped(ref, fzz, fzr, frz, frr, 0.0, tr);
        for (const bool axi : {false, true}) {
            const fe::Stretch s = fe::stretchOf(q, shape, axi);
            const double strain = fe::equivalentLogStrain(s);
            for (const double limit : {0.5, 1.0, 1.5}) {
                const bool below = fe::strainCertainlyBelow(s, fe::stretchRatioLimit(limit));
                ASSERT_FALSE(below && !(strain < limit))
                    << "trial " << trial << ": strain " << strain << " cleared for limit " << limit;
                if (strain < limit - slack) {
                    ASSERT_TRUE(below) << "trial " << trial << ": strain " << strain
                                       << " not cleared for limit " << limit;
                }
                cleared += below;
                ++evaluated;
            }
        }
    }
    std::printf("cleared without logarithms: %d of %d\n", cleared, evaluated);
}

namespace {

/// A free FE Al bar (planar, 2 mm x 0.2 mm) whose nodes are given a velocity field that
/// stretches it along z, so it rings elastically in its first axial mode. Returns the largest
/// geometric strain over the elements after `time` [us] with the chosen measure.
double ringingStrain(const std::string& measure, double time) {
    const nlohmann::json doc = {{"geometry", "planar"},
                                {"sph", {{"particle_spacing_mm", 0.05}}},
                                {"fe", {{"element_size_mm", 0.05}, {"erosion_strain", measure}}},
                                {"run",
                                 {{"end_time_us", time},
                                  {"stop_debris_speed_km_s", 0.0},
                                  {"stop_no_new_penetration_us", 0.0}}},
                                {"domain", {{"radius_mm", 5.0}}},
                                {"bodies",
                                 {{{"name", "bar"},
                                   {"role", "bumper"},
                                   {"material", "Al6061-T6"},
                                   {"discretization", "fe"},
                                   {"shape",
                                    {{"type", "rectangle"},
                                     {"z_min_mm", -1.0},
                                     {"z_max_mm", 1.0},
                                     {"r_min_mm", 1.0},
                                     {"r_max_mm", 1.2}}}}}}};
    solver::Simulation sim(test::makeScene(doc),
                           scene::sceneLibrary(nlohmann::json::object(), "<test>"));
    auto& nd = sim.finiteElements()->nodes();
    // v_z = 0.002 z km/s: a strain rate of 0.002/us, elastic (the bar's strain amplitude is
    // about 0.002 * 2 mm / (5 km/s * pi) ~ 2.5e-4, far below yield ~ 4e-3).
    for (std::size_t n = 0; n < nd.size(); ++n) {
        nd.vz[n] = 0.002 * nd.z[n];
    }
    sim.refreshRates();
    test::runUntil(sim, time);
    double largest = 0.0;
    for (const double g : sim.finiteElements()->erosionStrain()) {
        largest = std::max(largest, g);
    }
    return largest;
}

} // namespace

TEST(ErosionStrain, RingingDoesNotAccumulateInstantaneously) {
    // Ten periods of the bar's first axial mode (period 2 L / c ~ 0.8 us).
    const double instantaneous = ringingStrain("instantaneous", 8.0);
    const double incremental = ringingStrain("incremental", 8.0);
    // The instantaneous strain stays of the size of one amplitude; the incremental one
    // counts four amplitudes a period.
    EXPECT_LT(instantaneous, 1e-3) << instantaneous;
    EXPECT_GT(incremental, 10.0 * instantaneous)
        << "incremental " << incremental << ", instantaneous " << instantaneous;
}
