// The pair work kept for the compatible energy update (sph/PairWork.hpp), against the pair
// loop it comes from and against the kinetic energy its forces change:
//  * at the evaluation's own velocities each particle's heating is its energy rate de/dt (the
//    same terms, summed in another order: round-off);
//  * at any other velocities v, sum_i m_i (heating_i(v) + a_i . v_i) = 0 wherever the forces
//    are pair forces and the hoop forces' work is booked (planar, or axisymmetric away from
//    the axis): the internal energy a half kick pays is the kinetic energy it removes, which
//    is what makes the update conserve energy at any step. Next to the axis the axial excess
//    taken off the first column (sph/SphHydro.hpp) is not a pair force, and the balance holds
//    only to its size.
#include "PlanarSph.hpp"
#include "core/Error.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace hvi::sph;

namespace {

constexpr double kSpacing = 0.04;
constexpr double kRho = 2.7;
constexpr double kPi = 3.14159265358979323846;

/// A jittered Al lattice of rows x columns starting at r = rFirst, with random velocities
/// (+-1 km/s), pressures (0-20 GPa) and deviators (+-0.3 GPa).
ParticleSet lattice(int rows, int columns, double rFirst, bool axisymmetric, unsigned seed) {
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1), unit(-1.0, 1.0), frac(0.0, 1.0);
    ParticleSet ps;
    ps.enableStrength();
    for (int iz = 0; iz < rows; ++iz) {
        for (int ir = 0; ir < columns; ++ir) {
            const double z = (iz + 0.5 + jitter(gen)) * kSpacing;
            const double r = rFirst + (ir + jitter(gen)) * kSpacing;
            const double area = kRho * kSpacing * kSpacing;
            ps.add(z, r, unit(gen), unit(gen), axisymmetric ? 2.0 * kPi * r * area : area,
                   1.3 * kSpacing * (1.0 + 0.1 * jitter(gen)), kRho * (1.0 + 0.05 * unit(gen)),
                   0.0, 0);
            ps.p.back() = 20.0 * frac(gen);
            ps.cs.back() = 5.0 + frac(gen);
            ps.szz.back() = 0.3 * unit(gen);
            ps.srr.back() = 0.3 * unit(gen);
            ps.srz.back() = 0.3 * unit(gen);
        }
    }
    return ps;
}

HydroOptions keeping() {
    HydroOptions o;
    o.keepPairWork = true;
    return o;
}

/// Largest |heating at the evaluation's velocities - de/dt| over the slots, against the
/// largest |de/dt|.
void expectHeatingIsTheRate(const ParticleSet& ps, bool axisymmetric) {
    ParticleRates rates;
    const SphHydro hydro = hvi::test::evaluateIn(axisymmetric, ps, keeping(), rates);
    const PairWork& work = hydro.pairWork();
    ASSERT_EQ(work.slots(), ps.size());
    double worst = 0.0, scale = 0.0;
    for (std::size_t a = 0; a < work.slots(); ++a) {
        const auto i = static_cast<std::size_t>(work.particle(a));
        worst = std::max(worst, std::fabs(work.heating(a, ps.vz, ps.vr) - rates.de[i]));
        scale = std::max(scale, std::fabs(rates.de[i]));
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LE(worst, 1e-12 * scale) << "worst " << worst << " of " << scale;
}

/// sum m (heating(v) + a . v) over the set, and its scale sum m (|heating| + |a . v|), for
/// velocities v other than the evaluation's.
std::pair<double, double> balanceAt(const ParticleSet& ps, bool axisymmetric, unsigned seed) {
    ParticleRates rates;
    const SphHydro hydro = hvi::test::evaluateIn(axisymmetric, ps, keeping(), rates);
    const PairWork& work = hydro.pairWork();
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<double> vz(ps.size()), vr(ps.size());
    for (std::size_t i = 0; i < ps.size(); ++i) {
        vz[i] = unit(gen);
        vr[i] = unit(gen);
    }
    double sum = 0.0, scale = 0.0;
    for (std::size_t a = 0; a < work.slots(); ++a) {
        const auto i = static_cast<std::size_t>(work.particle(a));
        const double heat = work.heating(a, vz, vr);
        const double power = rates.az[i] * vz[i] + rates.ar[i] * vr[i];
        sum += ps.mass[i] * (heat + power);
        scale += ps.mass[i] * (std::fabs(heat) + std::fabs(power));
    }
    return {sum, scale};
}

} // namespace

TEST(PairWork, HeatingAtTheEvaluationsVelocitiesIsTheRatePlanar) {
    expectHeatingIsTheRate(lattice(12, 12, 0.0, false, 1), false);
}

TEST(PairWork, HeatingAtTheEvaluationsVelocitiesIsTheRateAtTheAxis) {
    // From the axis: mirror images, the hoop terms and the axial excess's work.
    expectHeatingIsTheRate(lattice(12, 12, 0.5 * kSpacing, true, 2), true);
}

TEST(PairWork, PaysWhatTheForcesTakePlanar) {
    const auto [sum, scale] = balanceAt(lattice(12, 12, 0.0, false, 3), false, 4);
    EXPECT_LT(std::fabs(sum), 1e-13 * scale) << sum << " of " << scale;
}

TEST(PairWork, PaysWhatTheForcesTakeAwayFromTheAxis) {
    // Hoop forces and their work on every particle; no mirror within reach (r >= 2.5 mm).
    const auto [sum, scale] = balanceAt(lattice(12, 12, 2.5, true, 5), true, 6);
    EXPECT_LT(std::fabs(sum), 1e-13 * scale) << sum << " of " << scale;
}

TEST(PairWork, CheckpointRoundTrip) {
    ParticleRates rates;
    const ParticleSet ps = lattice(6, 6, 0.5 * kSpacing, true, 7);
    const SphHydro hydro = hvi::test::evaluateIn(true, ps, keeping(), rates);
    hvi::io::CheckpointState state;
    hydro.pairWork().save(state, "w_");
    PairWork back;
    back.restore(state, "w_");
    ASSERT_EQ(back.slots(), hydro.pairWork().slots());
    for (std::size_t a = 0; a < back.slots(); ++a) {
        EXPECT_EQ(back.particle(a), hydro.pairWork().particle(a));
        EXPECT_EQ(back.heating(a, ps.vz, ps.vr), hydro.pairWork().heating(a, ps.vz, ps.vr));
    }
    state.doubles["w_gz"].pop_back();
    EXPECT_THROW(back.restore(state, "w_"), hvi::InputError);
}
