// Monaghan's artificial stress (SphHydro.hpp; Gray, Monaghan & Swift 2001, CMAME 190:6641,
// eqs. 23-27): it acts only on tensile principal stresses, pushes a pair in tension apart
// (the remedy for the tensile instability, where such pairs clump), vanishes in compression,
// and keeps the pair forces antisymmetric and the compatible energy split exact.
#include "PlanarSph.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace hvi::sph;

namespace {

constexpr double kSpacing = 0.04;
constexpr double kH = 1.3 * kSpacing;


/// A planar 3 x 3 lattice of Al-like particles at `spacing`, all with pressure p and deviator
/// (szz, srr, srz), the centre one moving at (vz, vr).
ParticleSet lattice(double spacing, double p, double szz, double srr, double srz) {
    ParticleSet ps;
    ps.enableStrength();
    const double mass = 2.7 * kSpacing * kSpacing;
    for (int a = -1; a <= 1; ++a) {
        for (int b = -1; b <= 1; ++b) {
            ps.add(a * spacing, 1.0 + b * spacing, 0.0, 0.0, mass, kH, 2.7, 0.0, 0);
            ps.p.back() = p;
            ps.cs.back() = 5.0;
            ps.szz.back() = szz;
            ps.srr.back() = srr;
            ps.srz.back() = srz;
        }
    }
    return ps;
}

ParticleRates evaluate(const ParticleSet& ps, double epsilon) {
    HydroOptions hydro;
    hydro.artificialStress = epsilon;
    hydro.spacingOverH = 1.0 / 1.3;
    ParticleRates rates;
    hvi::test::evaluatePlanar(ps, hydro, rates);
    return rates;
}

} // namespace

TEST(ArtificialStress, NothingInCompression) {
    // Pressure 2 GPa with a deviator whose principal stresses stay compressive.
    ParticleSet ps = lattice(0.8 * kSpacing, 2.0, 0.5, -0.3, 0.4);
    const ParticleRates off = evaluate(ps, 0.0);
    const ParticleRates on = evaluate(ps, 0.3);
    EXPECT_EQ(on.az, off.az);
    EXPECT_EQ(on.ar, off.ar);
    EXPECT_EQ(on.de, off.de);
}

TEST(ArtificialStress, PushesATensilePairApartAlongTheTension) {
    // Uniaxial tension along z (sigma_zz = 1 GPa, the others 0), particles squeezed to 0.8 of
    // their spacing: the corner particle at -z is pushed further to -z with epsilon = 0.3,
    // and nothing changes along r for the centre column (symmetric lattice).
    const double p = -1.0 / 3.0; // sigma = S - p I: S = (2/3, -1/3, -1/3) GPa
    ParticleSet ps = lattice(0.8 * kSpacing, p, 2.0 / 3.0, -1.0 / 3.0, 0.0);
    // sigma_rr = -1/3 + 1/3 = 0, sigma_zz = 2/3 + 1/3 = 1.
    const ParticleRates off = evaluate(ps, 0.0);
    const ParticleRates on = evaluate(ps, 0.3);
    const std::size_t left = 1; // (a = -1, b = 0)
    EXPECT_LT(on.az[left], off.az[left]) << "repulsion along the tension";
    EXPECT_NEAR(on.ar[left], off.ar[left], 1e-9 * std::fabs(off.az[left]));
    // Antisymmetric pair forces: the lattice's total force is unchanged (zero).
    double fz = 0.0, fr = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        fz += ps.mass[i] * on.az[i];
        fr += ps.mass[i] * on.ar[i];
        scale += ps.mass[i] * std::fabs(on.az[i]);
    }
    EXPECT_NEAR(fz, 0.0, 1e-12 * scale);
    EXPECT_NEAR(fr, 0.0, 1e-12 * scale);
}

TEST(ArtificialStress, WorkIsBalancedByInternalEnergy) {
    // A tensile lattice with a velocity field: the compatible split keeps
    // sum m (v . a + de/dt) = 0 with the artificial stress as without it.
    ParticleSet ps = lattice(0.85 * kSpacing, -0.5, 0.3, -0.1, 0.2);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        ps.vz[i] = 0.3 * std::sin(3.0 * static_cast<double>(i));
        ps.vr[i] = 0.2 * std::cos(5.0 * static_cast<double>(i));
    }
    const ParticleRates off = evaluate(ps, 0.0);
    const ParticleRates on = evaluate(ps, 0.3);
    double powerOn = 0.0, powerOff = 0.0, scale = 0.0, changed = 0.0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        const double m = ps.mass[i];
        powerOn += m * (ps.vz[i] * on.az[i] + ps.vr[i] * on.ar[i] + on.de[i]);
        powerOff += m * (ps.vz[i] * off.az[i] + ps.vr[i] * off.ar[i] + off.de[i]);
        scale += m * std::fabs(ps.vz[i] * on.az[i] + ps.vr[i] * on.ar[i]);
        changed += std::fabs(on.az[i] - off.az[i]);
    }
    EXPECT_GT(changed, 0.0) << "the lattice is in tension: the term must act";
    EXPECT_NEAR(powerOff, 0.0, 1e-12 * scale);
    EXPECT_NEAR(powerOn, 0.0, 1e-12 * scale);
}
