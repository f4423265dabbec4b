// The leapfrog's half-step state (solver/HalfStep.hpp) driven as solver::Simulation drives
// it: kick, drift with the half-step velocity, predict, kick again with the new rates. Under a
// constant acceleration the kick-drift-kick leapfrog is exact (z = z0 + v0 t + a t^2 / 2,
// v = v0 + a t); on a harmonic oscillator it keeps the energy within O(dt^2) and its error does
// not grow (symplectic). Every integrated field follows its rate; the strength fields only
// with strength.
#include "solver/HalfStep.hpp"

#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <omp.h>
#include <vector>

using namespace hvi;

namespace {

sph::ParticleSet oneParticle(bool strength) {
    sph::ParticleSet ps;
    if (strength) {
        ps.enableStrength();
    }
    ps.add(0.5, 1.0, 2.0, 0.0, 1.0, 0.1, 2.7, 0.0, 0);
    return ps;
}

/// One step of the leapfrog with rates from `ratesAt(ps, rates)`.
template <class RatesAt>
void step(sph::ParticleSet& ps, sph::ParticleRates& rt, solver::HalfStep& hs, double dt,
          RatesAt&& ratesAt) {
    const auto lanes = hs.lanes(ps, rt);
    const std::vector<int32_t> first{0};
    lanes.kick(first, ps.alive, 0.5 * dt);
    ps.z[0] += dt * hs.vz()[0];
    ps.r[0] += dt * hs.vr()[0];
    lanes.predict(first, ps.alive, 0.5 * dt);
    ratesAt(ps, rt);
    lanes.predict(first, ps.alive, 0.5 * dt);
}

} // namespace

TEST(HalfStep, ConstantAccelerationIsExact) {
    auto ps = oneParticle(false);
    sph::ParticleRates rt;
    rt.resize(1, false);
    auto constant = [](const sph::ParticleSet&, sph::ParticleRates& r) {
        r.az[0] = -3.0;
        r.ar[0] = 0.5;
        r.de[0] = 0.25;
        r.drho[0] = -0.1;
        r.dh[0] = 0.01;
    };
    constant(ps, rt);
    solver::HalfStep hs;
    hs.reset(ps);
    const double dt = 0.01;
    for (int n = 0; n < 100; ++n) {
        step(ps, rt, hs, dt, constant);
    }
    const double t = 1.0;
    EXPECT_NEAR(ps.z[0], 0.5 + 2.0 * t - 1.5 * t * t, 1e-12);
    EXPECT_NEAR(ps.r[0], 1.0 + 0.25 * t * t, 1e-12);
    EXPECT_NEAR(ps.vz[0], 2.0 - 3.0 * t, 1e-12);
    EXPECT_NEAR(ps.vr[0], 0.5 * t, 1e-12);
    EXPECT_NEAR(ps.e[0], 0.25 * t, 1e-12);
    EXPECT_NEAR(ps.rho[0], 2.7 - 0.1 * t, 1e-12);
    EXPECT_NEAR(ps.h[0], 0.1 + 0.01 * t, 1e-12);
}

TEST(HalfStep, HarmonicOscillatorKeepsItsEnergy) {
    // a = -w^2 (z - z0): E = v^2/2 + w^2 (z - z0)^2 / 2; the leapfrog's energy error is
    // bounded by about (w dt)^2 / 4 of E for all time.
    auto ps = oneParticle(false);
    sph::ParticleRates rt;
    rt.resize(1, false);
    const double w = 2.0, z0 = 0.5;
    auto spring = [&](const sph::ParticleSet& p, sph::ParticleRates& r) {
        r.az[0] = -w * w * (p.z[0] - z0);
    };
    spring(ps, rt);
    solver::HalfStep hs;
    hs.reset(ps);
    auto energy = [&] {
        return 0.5 * ps.vz[0] * ps.vz[0] + 0.5 * w * w * (ps.z[0] - z0) * (ps.z[0] - z0);
    };
    const double e0 = energy(), dt = 0.05;
    double worst = 0.0;
    for (int n = 0; n < 20000; ++n) { // about 64 periods
        step(ps, rt, hs, dt, spring);
        worst = std::max(worst, std::fabs(energy() - e0) / e0);
    }
    EXPECT_LT(worst, 0.25 * (w * dt) * (w * dt) * 1.05);
    EXPECT_GT(worst, 0.0);
}

TEST(HalfStep, StrengthFieldsOnlyWithStrength) {
    for (const bool strength : {false, true}) {
        auto ps = oneParticle(strength);
        sph::ParticleRates rt;
        rt.resize(1, strength);
        solver::HalfStep hs;
        hs.reset(ps);
        const auto lanes = hs.lanes(ps, rt);
        EXPECT_EQ(lanes.count, strength ? 8u : 5u);
        if (strength) {
            rt.dszz[0] = 1.0;
            rt.dsrr[0] = -2.0;
            rt.dsrz[0] = 0.5;
            const std::vector<int32_t> first{0};
            lanes.kick(first, ps.alive, 0.5);
            lanes.predict(first, ps.alive, 0.5);
            EXPECT_DOUBLE_EQ(ps.szz[0], 1.0);
            EXPECT_DOUBLE_EQ(ps.srr[0], -2.0);
            EXPECT_DOUBLE_EQ(ps.srz[0], 0.5);
        }
    }
}

TEST(HalfStep, HoldCopiesTheState) {
    auto ps = oneParticle(true);
    sph::ParticleRates rt;
    rt.resize(1, true);
    solver::HalfStep hs;
    hs.reset(ps);
    ps.vz[0] = 7.0;
    ps.szz[0] = 0.3;
    const auto lanes = hs.lanes(ps, rt);
    lanes.hold(0);
    EXPECT_DOUBLE_EQ(hs.vz()[0], 7.0);
    EXPECT_DOUBLE_EQ(lanes.half[5][0], 0.3);
    // The view contact constrains is vz, vr, e.
    auto view = hs.contactView();
    EXPECT_EQ(view.vz, &hs.vz());
    EXPECT_EQ(view.vr, &hs.vr());
}

TEST(HalfStep, ListedAlivePointsOnlyAtAnyThreadCount) {
    // Enough points for the threaded path (kParallelMinItems): every third listed, every
    // seventh dead. Listed alive points take state + dt/2 rate in every field; the rest keep
    // their half-step values bit for bit; one and two threads agree bitwise.
    constexpr std::size_t n = 30000;
    auto run = [&](int threads) {
        sph::ParticleSet ps;
        ps.enableStrength();
        for (std::size_t i = 0; i < n; ++i) {
            ps.add(0.01 * static_cast<double>(i), 1.0, 0.3, -0.2, 1.0, 0.1, 2.7, 0.0, 0);
            ps.alive[i] = i % 7 != 3;
            ps.szz[i] = 1e-3 * static_cast<double>(i % 11);
        }
        sph::ParticleRates rt;
        rt.resize(n, true);
        for (std::size_t i = 0; i < n; ++i) {
            rt.az[i] = std::sin(static_cast<double>(i));
            rt.dszz[i] = std::cos(static_cast<double>(i));
        }
        solver::HalfStep hs;
        hs.reset(ps);
        std::vector<int32_t> listed;
        for (std::size_t i = 0; i < n; i += 3) {
            listed.push_back(static_cast<int32_t>(i));
        }
        const int before = omp_get_max_threads();
        omp_set_num_threads(threads);
        hs.lanes(ps, rt).kick(listed, ps.alive, 0.25);
        omp_set_num_threads(before);
        std::vector<double> out = hs.vz();
        out.insert(out.end(), hs.lanes(ps, rt).half[5], hs.lanes(ps, rt).half[5] + n);
        for (std::size_t i = 0; i < n; ++i) {
            const bool moved = i % 3 == 0 && i % 7 != 3;
            const double vz = moved ? 0.3 + 0.25 * std::sin(static_cast<double>(i)) : 0.3;
            const double szz = 1e-3 * static_cast<double>(i % 11) +
                               (moved ? 0.25 * std::cos(static_cast<double>(i)) : 0.0);
            EXPECT_NEAR(out[i], vz, 1e-15) << "point " << i;
            EXPECT_NEAR(out[n + i], szz, 1e-15) << "point " << i;
        }
        return out;
    };
    EXPECT_EQ(run(1), run(2));
}
