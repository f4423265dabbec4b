#include "assess/ShieldLayout.hpp"

#include "scene/SceneLibrary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hvi::assess {

double ShieldLayout::depthOriginZ() const {
    if (bumper) {
        return bodies[*bumper].zRear;
    }
    double front = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (isTarget(b)) {
            front = std::min(front, bodies[b].zFront);
        }
    }
    return std::isfinite(front) ? front : 0.0;
}

bool ShieldLayout::isTarget(std::size_t body) const {
    return body < bodies.size() && bodies[body].role != scene::BodyRole::Projectile;
}

ShieldLayout shieldLayout(const scene::Scene& scene, const io::Snapshot& first) {
    ShieldLayout layout;
    layout.sceneId = scene.id;
    layout.axisymmetric = scene.geometry == scene::Geometry::Axisymmetric;
    layout.minDensityRatio = scene.sph.minDensityRatio;
    layout.particleSpacing = scene.sph.particleSpacing;
    layout.smoothingLengthFactor = scene.sph.smoothingLengthFactor;
    if (scene.hasFeBodies()) {
        layout.elementSize = scene.fe.elementSize;
    }
    layout.endTimeUs = scene.run.endTime;
    layout.stopDebrisSpeedKmS = scene.run.stopDebrisSpeed;
    layout.domainRadius = scene.domain.radius;

    // Reference densities: mass-weighted mean of each body's items in the first snapshot.
    std::vector<double> mass(scene.bodies.size(), 0.0), massRho(scene.bodies.size(), 0.0);
    const auto& p = first.particles;
    for (std::size_t i = 0; i < p.z.size(); ++i) {
        const auto b = static_cast<std::size_t>(p.bodyId[i]);
        if (p.bodyId[i] >= 0 && b < mass.size()) {
            mass[b] += p.mass[i];
            massRho[b] += p.mass[i] * p.density[i];
        }
    }
    std::vector<double> elementRho(scene.bodies.size(), 0.0);
    std::vector<std::size_t> elementCount(scene.bodies.size(), 0);
    if (first.fe) {
        const auto& e = first.fe->elements;
        for (std::size_t k = 0; k < e.bodyId.size(); ++k) {
            const auto b = static_cast<std::size_t>(e.bodyId[k]);
            if (e.bodyId[k] >= 0 && b < mass.size()) {
                elementRho[b] += e.density[k];
                ++elementCount[b];
            }
        }
    }

    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
        const auto& body = scene.bodies[b];
        BodyLayout bl;
        bl.name = body.name;
        bl.role = body.role;
        bl.fe = body.discretization == scene::Discretization::Fe;
        bl.zFront = body.shape.boundZMin();
        bl.zRear = body.shape.boundZMax();
        bl.rMin = body.shape.boundRMin();
        bl.rMax = body.shape.boundRMax();
        bl.spacing = body.spacing;
        if (mass[b] > 0.0) {
            bl.referenceDensity = massRho[b] / mass[b];
        } else if (elementCount[b] > 0) {
            bl.referenceDensity = elementRho[b] / static_cast<double>(elementCount[b]);
        }
        layout.bodies.push_back(bl);
    }

    for (std::size_t b = 0; b < layout.bodies.size(); ++b) {
        const auto& bl = layout.bodies[b];
        switch (bl.role) {
        case scene::BodyRole::Bumper:
            if (!layout.bumper || bl.zFront < layout.bodies[*layout.bumper].zFront) {
                layout.bumper = b;
            }
            break;
        case scene::BodyRole::RearWall:
            if (!layout.rearWall || bl.zRear > layout.bodies[*layout.rearWall].zRear) {
                layout.rearWall = b;
            }
            break;
        case scene::BodyRole::CoreLayer:
        case scene::BodyRole::CoreRing:
            layout.core.push_back(b);
            break;
        default:
            break;
        }
    }
    std::stable_sort(layout.core.begin(), layout.core.end(), [&](std::size_t a, std::size_t b) {
        return layout.bodies[a].zFront < layout.bodies[b].zFront;
    });
    return layout;
}

scene::Scene sceneOfRun(const io::RunFileReader& reader) {
    const nlohmann::json doc = reader.scene();
    const std::string label = reader.path().string();
    try {
        // The names the scene may use: the built-in library, the scene's own materials, and
        // what the run recorded it used (hvi-run --materials lays a library over the built-in
        // one without writing it into the scene).
        nlohmann::json materials = doc.is_object()
                                       ? doc.value("materials", nlohmann::json::object())
                                       : nlohmann::json::object();
        const nlohmann::json used = reader.materials();
        if (used.is_object()) {
            for (const auto& [name, spec] : used.items()) {
                if (!materials.contains(name)) {
                    materials[name] = spec;
                }
            }
        }
        const auto library = scene::sceneLibrary(materials, label);
        return scene::parseScene(doc, label, library.names());
    } catch (const InputError& e) {
        // The scene is a dataset of the run file: point into it.
        std::vector<InputIssue> issues = e.issues();
        for (auto& issue : issues) {
            issue.file = label;
            issue.pointer = "/scene" + issue.pointer;
            issue.expected = issue.expected.empty() ? "the scene hvi-run ran" : issue.expected;
        }
        throw InputError(std::move(issues));
    }
}

} // namespace hvi::assess
