// Runs a small scene in-process with solver::Simulation and writes what hvi-run would write:
// snapshots at the scene's snapshot interval, a history row every history_every_steps steps,
// and the run facts. For the hvi-assess golden test (the hvi-run tool itself lives elsewhere;
// this is the smallest faithful stand-in for its output loop).
#pragma once

#include "SceneRun.hpp"
#include "SyntheticRun.hpp"
#include "io/RunFileWriter.hpp"

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace hvi::test {

inline io::HistoryRow historyRowOf(const solver::Simulation& sim) {
    const auto t = sim.totals();
    io::HistoryRow row{};
    row.timeUs = sim.time();
    row.dtUs = sim.lastDt();
    row.step = sim.step();
    row.kineticEnergy = t.kinetic;
    row.internalEnergy = t.internal;
    row.totalEnergy = t.kinetic + t.internal;
    row.energyError = sim.energyError();
    row.deletedEnergy = t.deletedEnergy;
    row.mass = t.mass;
    row.momentumZ = t.momentumZ;
    row.aliveCount = static_cast<std::int64_t>(t.alive);
    row.deletedCount = static_cast<std::int64_t>(t.deleted);
    row.activeCount = static_cast<std::int64_t>(t.active);
    return row;
}

/// Runs `doc` to its end time or a stop rule and writes the run file at `path`.
inline std::filesystem::path simulateToRunFile(const nlohmann::json& doc,
                                               const std::filesystem::path& path) {
    const auto start = std::chrono::steady_clock::now();
    const scene::Scene scene = makeScene(doc);
    const auto library = scene::sceneLibrary(scene.materials, "<test>");
    solver::Simulation sim(scene, library);
    std::filesystem::remove(path);
    io::RunFileWriter writer(path, scene.resolved.dump(), "{}",
                             {{"tool", "hvi-assess golden test"}, {"input_file", "<test>"}});
    auto snapshot = [&] {
        const io::ParticleFields fields = fieldsOf(sim.particles());
        writer.writeSnapshot(sim.time(), sim.step(), io::viewOf(fields));
    };
    snapshot();
    writer.appendHistory(historyRowOf(sim));
    double nextSnapshot = scene.output.snapshotEvery;
    std::string stop = "end_time";
    while (true) {
        sim.advance();
        if (sim.step() % scene.output.historyEverySteps == 0) {
            writer.appendHistory(historyRowOf(sim));
        }
        const auto reason = sim.stopReason();
        if (sim.time() >= nextSnapshot * (1.0 - 1e-12) || reason) {
            snapshot();
            nextSnapshot += scene.output.snapshotEvery;
        }
        if (reason) {
            stop = *reason;
            break;
        }
    }
    writer.appendHistory(historyRowOf(sim));
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writer.finish({{"stop_reason", stop}, {"wall_time_s", wall}, {"steps", sim.step()}});
    return path;
}

} // namespace hvi::test
