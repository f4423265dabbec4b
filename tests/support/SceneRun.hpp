// Builds and runs small scenes in-process for the verification tests.
#pragma once

#include "fe/FeSolid.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneLibrary.hpp"
#include "solver/Simulation.hpp"

#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>

namespace hvi::test {

/// A diagnostic override from the environment (a spacing, a size), or the test's value.
inline double envOr(const char* name, double fallback) {
    const char* value = std::getenv(name);
    return value ? std::atof(value) : fallback;
}

/// Parses a scene document (validated like a file) with the built-in materials.
inline scene::Scene makeScene(const nlohmann::json& doc) {
    const auto library =
        scene::sceneLibrary(doc.value("materials", nlohmann::json::object()), "<test>");
    return scene::parseScene(doc, "<test>", library.names());
}

/// Mean of an FE element's four nodes: position [mm] and velocity [km/s].
struct ElementCentroid {
    double z = 0.0, r = 0.0, vz = 0.0, vr = 0.0;
};

inline ElementCentroid elementCentroid(const fe::FeSolid& fe, std::size_t element) {
    ElementCentroid c;
    for (int a = 0; a < 4; ++a) {
        const auto n = static_cast<std::size_t>(fe.elements().node(element, a));
        c.z += 0.25 * fe.nodes().z[n];
        c.r += 0.25 * fe.nodes().r[n];
        c.vz += 0.25 * fe.nodes().vz[n];
        c.vr += 0.25 * fe.nodes().vr[n];
    }
    return c;
}

/// Runs until `until` [us] or a stop rule; calls `each` after every step if given.
inline void runUntil(solver::Simulation& sim, double until,
                     const std::function<void(const solver::Simulation&)>& each = {}) {
    while (sim.time() < until * (1.0 - 1e-12)) {
        sim.advance();
        if (each) {
            each(sim);
        }
        if (sim.stopReason() && *sim.stopReason() != "end_time") {
            break;
        }
    }
}

} // namespace hvi::test
