#include "sph/ParticleGenerator.hpp"

#include "core/Units.hpp"

#include <cmath>

namespace hvi::sph {

namespace {
/// Number of lattice cells across a length, at least one.
long cellsAcross(double length, double spacing) {
    return std::max(1L, std::lround(length / spacing));
}
} // namespace

BodyFill fillBody(const scene::Body& body, int32_t bodyIndex, double rho0, double e0,
                  double smoothingFactor, bool axisymmetric, ParticleSet& ps) {
    BodyFill fill;
    fill.first = ps.size();
    const scene::Shape& s = body.shape;
    const double dx = body.spacing;
    const double twoPi = 2.0 * units::kPi;
    auto ringMass = [&](double r, double dz, double dr) {
        return (axisymmetric ? twoPi * r : 1.0) * rho0 * dz * dr;
    };
    if (s.kind == scene::ShapeKind::Sphere) {
        const long n = cellsAcross(s.radius, dx);
        const double d = s.radius / static_cast<double>(n);
        const double h = smoothingFactor * d;
        double lattice = 0.0;
        for (long iz = -n; iz < n; ++iz) {
            const double z = s.centerZ + (static_cast<double>(iz) + 0.5) * d;
            for (long ir = axisymmetric ? 0 : -n; ir < n; ++ir) {
                const double r = (static_cast<double>(ir) + 0.5) * d;
                const double dzc = z - s.centerZ;
                if (dzc * dzc + r * r > s.radius * s.radius) {
                    continue;
                }
                const double m = ringMass(std::fabs(r), d, d);
                lattice += m;
                ps.add(z, r, body.velocityZ, body.velocityR, m, h, rho0, e0, bodyIndex);
            }
        }
        // Exact body mass: a sphere (axisymmetric) or a disc per unit depth (planar).
        const double exact = axisymmetric ? (4.0 / 3.0) * units::kPi * std::pow(s.radius, 3) * rho0
                                          : units::kPi * s.radius * s.radius * rho0;
        const double scale = lattice > 0.0 ? exact / lattice : 1.0;
        for (std::size_t i = fill.first; i < ps.size(); ++i) {
            ps.mass[i] *= scale;
        }
        fill.spacing = d;
    } else {
        const double z0 = s.boundZMin(), z1 = s.boundZMax();
        const double r0 = s.boundRMin(), r1 = s.boundRMax();
        const long nz = cellsAcross(z1 - z0, dx);
        const long nr = cellsAcross(r1 - r0, dx);
        const double dz = (z1 - z0) / static_cast<double>(nz);
        const double dr = (r1 - r0) / static_cast<double>(nr);
        const double h = smoothingFactor * std::max(dz, dr);
        for (long iz = 0; iz < nz; ++iz) {
            const double z = z0 + (static_cast<double>(iz) + 0.5) * dz;
            for (long ir = 0; ir < nr; ++ir) {
                const double r = r0 + (static_cast<double>(ir) + 0.5) * dr;
                ps.add(z, r, body.velocityZ, body.velocityR, ringMass(r, dz, dr), h, rho0, e0,
                       bodyIndex);
            }
        }
        fill.spacing = std::max(dz, dr);
    }
    fill.count = ps.size() - fill.first;
    for (std::size_t i = fill.first; i < ps.size(); ++i) {
        fill.mass += ps.mass[i];
    }
    return fill;
}

} // namespace hvi::sph
