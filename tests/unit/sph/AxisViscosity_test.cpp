// The artificial viscosity near the axis (SphHydro.cpp, docs/formulation.md "The axis").
// Monaghan's Pi_ij acts as a viscous pressure. In RZ the radius-weighted pair sum gives every
// isotropic term the in-plane part of the cylindrical divergence, -(q/r) e_r for a viscous
// pressure q; the hoop stress -q cancels it, as the hoop term cancels it for p. Without that
// hoop part a uniaxial compression, which has no radial motion and no radial pressure
// gradient, pulled every particle towards the axis with a force growing as 1/r (measured
// -0.058/r km/s/us on the lattice below; -0.67 km/s/us on the first column) and held the first
// particle column of a shocked bumper on the axis.
//
// Exact answer: for a velocity field linear in (z, r) on a uniform lattice every pair's Pi
// depends only on the pair's offset, the lattice with its mirror images is symmetric about
// each particle, so the area-weighted viscous force has no radial part at all.
#include "PlanarSph.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace hvi::sph;

namespace {

constexpr double kSpacing = 0.04;
constexpr double kRho = 2.7;
constexpr double kPi = 3.14159265358979323846;
constexpr int kRows = 40;    // along z
constexpr int kColumns = 40; // along r, from the axis

/// A uniform Al-density lattice from the axis (first column at r = spacing/2), zero pressure,
/// moving with v = (-compression (z - z_mid), expansion r).
ParticleSet lattice(double compressionPerUs, double expansionPerUs) {
    ParticleSet ps;
    const double zMid = 0.5 * kRows * kSpacing;
    for (int iz = 0; iz < kRows; ++iz) {
        for (int ir = 0; ir < kColumns; ++ir) {
            const double z = (iz + 0.5) * kSpacing, r = (ir + 0.5) * kSpacing;
            ps.add(z, r, -compressionPerUs * (z - zMid), expansionPerUs * r,
                   2.0 * kPi * r * kRho * kSpacing * kSpacing, 1.3 * kSpacing, kRho, 0.0, 0);
            ps.p.back() = 0.0;
            ps.cs.back() = 5.0;
        }
    }
    return ps;
}

struct AxisForces {
    double maxRadialAcceleration = 0.0; ///< over the middle rows' first 10 columns [km/s/us]
    double minHeating = 0.0;            ///< smallest de/dt there: > 0 shows Pi is acting
    double energyRate = 0.0;            ///< sum m (v.a + de/dt) over all particles
    double energyScale = 0.0;           ///< sum m |de/dt|
};

AxisForces evaluate(const ParticleSet& ps) {
    ParticleRates rates;
    hvi::test::evaluateAxisymmetric(ps, HydroOptions{}, rates);
    AxisForces f;
    f.minHeating = INFINITY;
    for (int iz = kRows / 2 - 5; iz < kRows / 2 + 5; ++iz) {
        for (int ir = 0; ir < 10; ++ir) {
            const std::size_t i = static_cast<std::size_t>(iz * kColumns + ir);
            f.maxRadialAcceleration = std::max(f.maxRadialAcceleration, std::fabs(rates.ar[i]));
            f.minHeating = std::min(f.minHeating, rates.de[i]);
        }
    }
    for (std::size_t i = 0; i < ps.size(); ++i) {
        f.energyRate +=
            ps.mass[i] * (ps.vz[i] * rates.az[i] + ps.vr[i] * rates.ar[i] + rates.de[i]);
        f.energyScale += ps.mass[i] * std::fabs(rates.de[i]);
    }
    return f;
}

} // namespace

TEST(AxisViscosity, UniaxialCompressionHasNoRadialForce) {
    // Compression at 2 /us: Pi is active on every approaching pair, heating each particle.
    const AxisForces f = evaluate(lattice(2.0, 0.0));
    EXPECT_GT(f.minHeating, 0.0);
    // Before the viscous hoop term: 0.67 km/s/us on the first column. The pair sums of a
    // 40 x 40 lattice cancel to round-off (~1e-13 measured).
    EXPECT_LT(f.maxRadialAcceleration, 1e-9) << "the viscous pressure pulls towards the axis";
}

TEST(AxisViscosity, CompressionWithRadialExpansionHasNoRadialForce) {
    // Axial compression with a homologous radial expansion (v_r = r/us), the flow behind a
    // plate's impact shock: pairs along z approach, pairs along r recede.
    const AxisForces f = evaluate(lattice(2.0, 1.0));
    EXPECT_GT(f.minHeating, 0.0);
    EXPECT_LT(f.maxRadialAcceleration, 1e-9);
}

TEST(AxisViscosity, CompatibleEnergyStaysExact) {
    // The viscous hoop force's work is booked on the particle it acts on, so kinetic plus
    // internal energy rates still cancel over the set.
    const AxisForces f = evaluate(lattice(2.0, 1.0));
    EXPECT_LT(std::fabs(f.energyRate), 1e-12 * f.energyScale)
        << "energy rate " << f.energyRate << " of " << f.energyScale;
}
