// A scene that hvi-run --check accepts and that is small is set up (particle generator, FE
// mesh, contact, materials) and advanced a few steps, so the fuzz targets of hvi-run's inputs
// also reach the code a scene's and a material's numbers drive.
#pragma once

#include "app/RunScene.hpp"
#include "core/Error.hpp"
#include "solver/Simulation.hpp"

#include <string>

namespace hvi::fuzz {

inline constexpr double kMaxPointsToRun = 3000.0; // keeps one input well under a second
inline constexpr int kStepsToRun = 5;

inline void runFirstSteps(const std::string& scene, const app::SceneOverrides& overrides) {
    try {
        const auto loaded = app::loadRunScene(scene, overrides, 1e9);
        if (loaded.estimatedPoints > kMaxPointsToRun) {
            return;
        }
        solver::Simulation sim(loaded.scene, loaded.library);
        for (int i = 0; i < kStepsToRun && !sim.stopReason(); ++i) {
            sim.advance();
        }
    } catch (const InputError&) {
    } catch (const RuntimeFailure&) {
    }
}

} // namespace hvi::fuzz
