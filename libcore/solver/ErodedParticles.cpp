#include "solver/ErodedParticles.hpp"

#include "core/Units.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::solver {

namespace {

struct Corners {
    double z = 0.0, r = 0.0; ///< mean of the corner positions [mm]
};

Corners cornerMean(const fe::NodeSet& nodes, const fe::ElementSet& elements, std::size_t e) {
    Corners c;
    for (int a = 0; a < 4; ++a) {
        const auto n = static_cast<std::size_t>(elements.node(e, a));
        c.z += 0.25 * nodes.z[n];
        c.r += 0.25 * nodes.r[n];
    }
    return c;
}

} // namespace

std::size_t ErodedParticles::reserve(const fe::BodyMesh& mesh, int32_t bodyIndex, double rho0,
                                     const fe::NodeSet& nodes, const fe::ElementSet& elements,
                                     sph::ParticleSet& particles) {
    Range range;
    range.firstElement = mesh.firstElement;
    range.elementCount = mesh.elementCount;
    range.firstParticle = particles.size();
    const double h = m_smoothingFactor * mesh.elementSize;
    for (std::size_t k = 0; k < mesh.elementCount; ++k) {
        const Corners c = cornerMean(nodes, elements, mesh.firstElement + k);
        particles.add(c.z, c.r, 0.0, 0.0, 0.0, h, rho0, 0.0, bodyIndex);
        particles.alive.back() = 0;
    }
    m_ranges.push_back(range);
    return range.firstParticle;
}

int32_t ErodedParticles::slotOf(std::size_t element) const {
    for (const Range& range : m_ranges) {
        if (element >= range.firstElement && element < range.firstElement + range.elementCount) {
            return static_cast<int32_t>(range.firstParticle + (element - range.firstElement));
        }
    }
    return -1;
}

std::vector<int32_t> ErodedParticles::convert(const std::vector<int32_t>& erodedElements,
                                              const fe::ElementSet& elements, fe::NodeSet& nodes,
                                              sph::ParticleSet& particles,
                                              const std::vector<double>& rhoMin,
                                              const std::vector<double>& rhoMax) const {
    std::vector<int32_t> created;
    const bool strength = particles.hasStrength() && elements.hasStrength();
    for (const int32_t element : erodedElements) {
        const auto e = static_cast<std::size_t>(element);
        const int32_t slot = slotOf(e);
        if (slot < 0) {
            continue;
        }
        const auto i = static_cast<std::size_t>(slot);
        // Mass, momentum and kinetic energy taken from the corners.
        const double quarter = 0.25 * elements.mass[e];
        double mass = 0.0, pz = 0.0, pr = 0.0, kinetic = 0.0;
        for (int a = 0; a < 4; ++a) {
            const auto n = static_cast<std::size_t>(elements.node(e, a));
            // A node that has lost its last element gives up all it has left (its mass
            // reaches exactly 0, whatever the rounding of the quarters).
            const double share =
                nodes.elementCount[n] == 0 ? nodes.mass[n] : std::min(quarter, nodes.mass[n]);
            nodes.mass[n] -= share; // exactly 0 when it took all
            if (nodes.elementCount[n] == 0) {
                nodes.alive[n] = 0;
            }
            mass += share;
            pz += share * nodes.vz[n];
            pr += share * nodes.vr[n];
            kinetic += 0.5 * share * (nodes.vz[n] * nodes.vz[n] + nodes.vr[n] * nodes.vr[n]);
        }
        if (!(mass > 0.0)) {
            continue; // its corners had nothing left (cannot happen with lumped masses)
        }
        const double vz = pz / mass, vr = pr / mass;
        const double averagedOut = std::max(0.0, kinetic - 0.5 * mass * (vz * vz + vr * vr));
        const auto body = static_cast<std::size_t>(elements.body[e]);
        const double rho = std::clamp(elements.rho[e], rhoMin[body], rhoMax[body]);
        const Corners c = cornerMean(nodes, elements, e);
        const double planeArea =
            m_axisymmetric ? mass / (2.0 * units::kPi * std::max(c.r, 1e-12) * rho) : mass / rho;
        const double h = m_smoothingFactor * std::sqrt(planeArea);
        particles.z[i] = c.z;
        // Never on the axis (the ring would have no volume): at least the clearance the time
        // loop keeps particles at.
        particles.r[i] = m_axisymmetric ? std::max(c.r, 0.1 * h) : c.r;
        particles.vz[i] = vz;
        particles.vr[i] = vr;
        particles.mass[i] = mass;
        particles.h[i] = h;
        particles.rho[i] = rho;
        particles.e[i] = elements.e[e] * elements.mass[e] / mass + averagedOut / mass;
        particles.alive[i] = 1;
        static_assert(sameNames(sph::kParticleStrengthFields, fe::kElementStrengthFields));
        for (std::size_t f = 0; f < fe::kElementStrengthFields.size() && strength; ++f) {
            (particles.*sph::kParticleStrengthFields[f].member)[i] =
                (elements.*fe::kElementStrengthFields[f].member)[e];
        }
        created.push_back(slot);
    }
    std::sort(created.begin(), created.end());
    return created;
}

} // namespace hvi::solver
