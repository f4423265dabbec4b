#include "solver/SceneAssembly.hpp"

#include "fe/FeSolid.hpp"

#include <algorithm>
#include <limits>

namespace hvi::solver {

namespace {

/// The strength arrays a scene needs: particles with strength (SPH bodies, and FE bodies
/// whose eroded elements become particles that keep their stress state), elements with it.
struct StrengthNeeds {
    bool particles = false, elements = false;
};

StrengthNeeds strengthNeeds(const scene::Scene& scene,
                            const std::vector<material::MaterialSpec>& specs) {
    StrengthNeeds needs;
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
        const auto& body = scene.bodies[b];
        const bool strength = body.strength && specs[b].hasStrength();
        if (body.discretization == scene::Discretization::Fe) {
            needs.elements = needs.elements || strength;
            needs.particles = needs.particles || (strength && scene.fe.erodedToParticles);
        } else {
            needs.particles = needs.particles || strength;
        }
    }
    return needs;
}

/// An FE body meshed into the node and element sets, with its reserve of particle slots.
void assembleFeBody(const scene::Scene& scene, std::size_t b, material::BodyMaterial bm,
                    SceneAssembly& a) {
    const auto& body = scene.bodies[b];
    const bool axi = scene.geometry == scene::Geometry::Axisymmetric;
    const double rho0 = a.specs[b].referenceDensity;
    const fe::BodyMesh mesh =
        fe::meshBody(body, static_cast<int32_t>(b), rho0, 0.0, axi, a.fe.nodes, a.fe.elements);
    // The particles its eroded elements will become, held in reserve (or none).
    sph::BodyFill reserve;
    reserve.first = a.particles.size();
    reserve.spacing = mesh.elementSize;
    if (a.fe.eroded) {
        a.fe.eroded->reserve(mesh, static_cast<int32_t>(b), rho0, a.fe.nodes, a.fe.elements,
                             a.particles);
        reserve.count = a.particles.size() - reserve.first;
    }
    a.fills.push_back(reserve);
    material::BodyMaterial em = bm;
    bm.first = reserve.first;
    bm.count = reserve.count;
    em.first = mesh.firstElement;
    em.count = mesh.elementCount;
    a.particleMaterials.push_back(bm);
    a.fe.materials.push_back(em);
    a.fe.contactBodies.push_back({true, mesh.elementSize});
}

void assembleSphBody(const scene::Scene& scene, std::size_t b, material::BodyMaterial bm,
                     SceneAssembly& a) {
    const bool axi = scene.geometry == scene::Geometry::Axisymmetric;
    a.fills.push_back(sph::fillBody(scene.bodies[b], static_cast<int32_t>(b),
                                    a.specs[b].referenceDensity, 0.0,
                                    scene.sph.smoothingLengthFactor, axi, a.particles));
    material::BodyMaterial em = bm;
    em.count = 0; // no elements
    bm.first = a.fills.back().first;
    bm.count = a.fills.back().count;
    a.particleMaterials.push_back(bm);
    a.fe.materials.push_back(em);
    a.fe.contactBodies.push_back({false, a.fills.back().spacing});
}

} // namespace

SceneAssembly assembleScene(const scene::Scene& scene, const material::MaterialLibrary& library) {
    SceneAssembly a;
    a.specs.reserve(scene.bodies.size());
    for (const auto& body : scene.bodies) {
        a.specs.push_back(library.get(body.material));
    }
    const StrengthNeeds needs = strengthNeeds(scene, a.specs);
    if (scene.hasFeBodies() && scene.fe.erodedToParticles) {
        a.fe.eroded = std::make_unique<ErodedParticles>(
            scene.geometry == scene::Geometry::Axisymmetric, scene.sph.smoothingLengthFactor);
    }
    if (needs.elements) {
        a.fe.elements.enableStrength();
    }
    a.minSpacing = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
        const auto& body = scene.bodies[b];
        const auto& spec = a.specs[b];
        material::BodyMaterial bm;
        bm.spec = &a.specs[b];
        bm.strength = body.strength && spec.hasStrength();
        bm.minDensity = scene.sph.minDensityRatio * spec.referenceDensity;
        bm.maxDensity = material::densityCeiling(spec);
        if (body.discretization == scene::Discretization::Fe) {
            assembleFeBody(scene, b, bm, a);
        } else {
            assembleSphBody(scene, b, bm, a);
        }
        a.fe.erosionFactors.push_back(body.erosionFactor);
        a.minSpacing = std::min(a.minSpacing, a.fills.back().spacing);
    }
    // Strength arrays for every particle of every body (ParticleSet keeps an explicit flag,
    // so the order relative to the fill does not matter).
    if (needs.particles) {
        a.particles.enableStrength();
    }
    return a;
}

} // namespace hvi::solver
