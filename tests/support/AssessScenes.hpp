// Scenes and helpers shared by the hvi-assess metric tests: a Whipple shield (projectile,
// bumper, rear wall) and a foam-like layer stack, at a coarse spacing so each test writes
// and reads a few thousand particles.
#pragma once

#include "SyntheticRun.hpp"
#include "TestPaths.hpp"
#include "assess/Assessment.hpp"
#include "io/RunFileReader.hpp"

#include <string>

namespace hvi::test {

/// Places `count` projectile particles at z, spread over r in [0, 0.5), moving at vz.
inline void placeDebris(const SyntheticRun& run, io::ParticleFields& snap, std::size_t count,
                        double z, double vz) {
    std::size_t placed = 0;
    run.forBody(snap, "projectile", [&](std::size_t i) {
        if (placed < count) {
            snap.z[i] = z;
            snap.r[i] = 0.025 + 0.05 * static_cast<double>(placed % 10);
            snap.vz[i] = vz;
            ++placed;
        }
    });
}

/// Projectile (r 0.5 mm), bumper z in [0, 0.5], rear wall z in [5, 6]; plates 5 mm wide.
inline nlohmann::json whippleScene(double spacing = 0.05) {
    return {{"id", "whipple-test"},
            {"sph", {{"particle_spacing_mm", spacing}}},
            {"run", {{"end_time_us", 2.0}}},
            {"bodies",
             {projectileBody(0.5, 3.0), plateBody("bumper", "bumper", 0.0, 0.5, 5.0),
              plateBody("rear", "rear_wall", 5.0, 1.0, 5.0)}}};
}

/// Projectile, bumper [0, 0.25], five core layers 0.2 mm thick at z = 2, 4, 6, 8, 10 and a
/// rear wall [12, 12.5]; 4 mm wide.
inline nlohmann::json layerScene() {
    nlohmann::json bodies = {projectileBody(0.5, 3.0),
                             plateBody("bumper", "bumper", 0.0, 0.25, 4.0)};
    for (int k = 1; k <= 5; ++k) {
        bodies.push_back(plateBody("layer" + std::to_string(k), "core_layer", 2.0 * k, 0.2, 4.0));
    }
    bodies.push_back(plateBody("rear", "rear_wall", 12.0, 0.5, 4.0));
    return {{"id", "layers-test"}, {"sph", {{"particle_spacing_mm", 0.05}}}, {"bodies", bodies}};
}

/// Writes `run` to the build tree and assesses it.
inline assess::Assessment assessSynthetic(const SyntheticRun& run, const std::string& name,
                                          const assess::AssessOptions& options = {}) {
    const auto path = run.write(tempPath(name + ".h5"));
    const io::RunFileReader reader(path);
    return assess::assessRun(reader, options);
}

} // namespace hvi::test
