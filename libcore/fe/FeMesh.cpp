#include "fe/FeMesh.hpp"

#include "core/Error.hpp"
#include "core/Units.hpp"
#include "fe/QuadKinematics.hpp"
#include "geometry/GmshMesher.hpp"

namespace hvi::fe {

void ElementSet::enableStrength() {
    m_withStrength = true;
    for (const auto& f : kElementStrengthFields) {
        (this->*f.member).assign(size(), 0.0);
    }
}

BodyMesh meshBody(const scene::Body& body, int32_t bodyIndex, double rho0, double e0,
                  bool axisymmetric, NodeSet& nodes, ElementSet& elements) {
    const scene::Shape& s = body.shape;
    if (s.kind == scene::ShapeKind::Sphere) {
        throw InputError("<scene>", "/bodies/" + std::to_string(bodyIndex) + "/discretization",
                         "a sphere cannot be meshed with finite elements",
                         "\"sph\" for spherical bodies (projectiles)");
    }
    BodyMesh mesh;
    const double z0 = s.boundZMin(), z1 = s.boundZMax();
    const double r0 = s.boundRMin(), r1 = s.boundRMax();
    const std::size_t nz = geometry::GmshMesher::divisions(z1 - z0, body.spacing);
    const std::size_t nr = geometry::GmshMesher::divisions(r1 - r0, body.spacing);
    const double dz = (z1 - z0) / static_cast<double>(nz);
    const double dr = (r1 - r0) / static_cast<double>(nr);
    mesh.divisionsZ = nz;
    mesh.divisionsR = nr;
    mesh.elementSize = std::max(dz, dr);
    mesh.firstNode = nodes.size();
    mesh.firstElement = elements.size();

    // Nodes, r fastest: node (iz, ir) at firstNode + iz (nr + 1) + ir.
    for (std::size_t iz = 0; iz <= nz; ++iz) {
        for (std::size_t ir = 0; ir <= nr; ++ir) {
            const double r = ir == nr ? r1 : r0 + static_cast<double>(ir) * dr;
            nodes.z.push_back(iz == nz ? z1 : z0 + static_cast<double>(iz) * dz);
            nodes.r.push_back(r);
            nodes.vz.push_back(body.velocityZ);
            nodes.vr.push_back(body.velocityR);
            nodes.mass.push_back(0.0);
            nodes.fz.push_back(0.0);
            nodes.fr.push_back(0.0);
            nodes.body.push_back(bodyIndex);
            nodes.alive.push_back(1);
            nodes.onAxis.push_back(axisymmetric && r == 0.0 ? 1 : 0);
            nodes.elementCount.push_back(0);
        }
    }
    mesh.nodeCount = nodes.size() - mesh.firstNode;
    const auto nodeIndex = [&](std::size_t iz, std::size_t ir) {
        return static_cast<int32_t>(mesh.firstNode + iz * (nr + 1) + ir);
    };
    const bool strength = elements.hasStrength();
    for (std::size_t iz = 0; iz < nz; ++iz) {
        for (std::size_t ir = 0; ir < nr; ++ir) {
            // Counter-clockwise with z to the right and r up.
            const std::array<int32_t, 4> corner{nodeIndex(iz, ir), nodeIndex(iz + 1, ir),
                                                nodeIndex(iz + 1, ir + 1), nodeIndex(iz, ir + 1)};
            QuadState q;
            for (int a = 0; a < 4; ++a) {
                const auto n = static_cast<std::size_t>(corner[static_cast<std::size_t>(a)]);
                q.z[static_cast<std::size_t>(a)] = nodes.z[n];
                q.r[static_cast<std::size_t>(a)] = nodes.r[n];
            }
            const QuadGeometry g = quadGeometry(q);
            const double volume = axisymmetric ? 2.0 * units::kPi * g.centroidR * g.area : g.area;
            const double m = rho0 * volume;
            for (const int32_t n : corner) {
                elements.connectivity.push_back(n);
                nodes.mass[static_cast<std::size_t>(n)] += 0.25 * m;
                ++nodes.elementCount[static_cast<std::size_t>(n)];
            }
            elements.body.push_back(bodyIndex);
            elements.alive.push_back(1);
            elements.mass.push_back(m);
            elements.rho.push_back(rho0);
            elements.e.push_back(e0);
            elements.p.push_back(0.0);
            elements.cs.push_back(0.0);
            elements.q.push_back(0.0);
            elements.geometricStrain.push_back(0.0);
            if (strength) {
                for (const auto& f : kElementStrengthFields) {
                    (elements.*f.member).push_back(0.0);
                }
            }
        }
    }
    mesh.elementCount = elements.size() - mesh.firstElement;
    return mesh;
}

NodeCorners NodeCorners::of(const ElementSet& el, std::size_t nodeCount, bool aliveOnly) {
    NodeCorners t;
    t.offset.assign(nodeCount + 1, 0);
    for (std::size_t i = 0; i < el.size(); ++i) {
        if (aliveOnly && !el.alive[i]) {
            continue;
        }
        for (int a = 0; a < 4; ++a) {
            ++t.offset[static_cast<std::size_t>(el.node(i, a)) + 1];
        }
    }
    for (std::size_t n = 0; n < nodeCount; ++n) {
        t.offset[n + 1] += t.offset[n];
    }
    t.corners.assign(static_cast<std::size_t>(t.offset[nodeCount]), 0);
    std::vector<int64_t> fill(t.offset.begin(), t.offset.end() - 1);
    for (std::size_t i = 0; i < el.size(); ++i) {
        if (aliveOnly && !el.alive[i]) {
            continue;
        }
        for (int a = 0; a < 4; ++a) {
            const auto n = static_cast<std::size_t>(el.node(i, a));
            t.corners[static_cast<std::size_t>(fill[n]++)] = static_cast<int32_t>(4 * i) + a;
        }
    }
    return t;
}

} // namespace hvi::fe
