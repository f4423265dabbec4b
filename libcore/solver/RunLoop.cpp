#include "solver/RunLoop.hpp"

#include "core/Error.hpp"
#include "core/Fingerprint.hpp"
#include "io/AtomicOutput.hpp"
#include "io/Checkpoint.hpp"
#include "io/JsonText.hpp"
#include "io/RunFileReader.hpp"
#include "solver/StateView.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <omp.h>

namespace hvi::solver {

std::atomic<bool> g_stopRequested{false};

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

io::HistoryRow historyRow(const Simulation& sim) {
    const Totals t = sim.totals();
    io::HistoryRow row;
    row.timeUs = sim.time();
    row.dtUs = sim.lastDt();
    row.step = sim.step();
    row.kineticEnergy = t.kinetic;
    row.internalEnergy = t.internal;
    row.totalEnergy = t.kinetic + t.internal;
    row.energyError =
        io::relativeEnergyError(row.totalEnergy, t.deletedEnergy, sim.initialEnergy());
    row.deletedEnergy = t.deletedEnergy;
    row.mass = t.mass;
    row.momentumZ = t.momentumZ;
    row.aliveCount = static_cast<std::int64_t>(t.alive);
    row.deletedCount = static_cast<std::int64_t>(t.deleted);
    row.activeCount = static_cast<std::int64_t>(t.active);
    return row;
}

std::string formatDuration(double seconds) {
    char buf[32];
    if (!std::isfinite(seconds) || seconds < 0) {
        return "?";
    }
    if (seconds < 120) {
        std::snprintf(buf, sizeof buf, "%.0f s", seconds);
    } else if (seconds < 7200) {
        std::snprintf(buf, sizeof buf, "%.1f min", seconds / 60);
    } else {
        std::snprintf(buf, sizeof buf, "%.1f h", seconds / 3600);
    }
    return buf;
}

} // namespace

io::CheckpointState checkpointOf(const Simulation& sim, double maxEnergyError) {
    io::CheckpointState s;
    sim.save(s);
    s.extra["max_energy_error"] = maxEnergyError;
    return s;
}

namespace {

/// What a checkpoint must share with the run that resumes it: the scene and the material
/// library as resolved, less what only says how long to run and what to write (the end time,
/// the step cap, the stop rules, the output cadence), which a resumed run may change.
std::string sceneFingerprint(const std::string& sceneText, const std::string& materialsText) {
    nlohmann::json scene = nlohmann::json::parse(sceneText);
    if (scene.contains("run") && scene["run"].is_object()) {
        for (const char* key : {"end_time_us", "max_steps", "stop_debris_speed_km_s",
                                "stop_no_new_penetration_us", "stop_on_rear_wall_perforation"}) {
            scene["run"].erase(key);
        }
    }
    scene.erase("output");
    return core::fingerprint(io::jsonText(scene) + '\n' + materialsText);
}

/// Where the run's output schedule stands at a checkpoint: the snapshots and history rows
/// written on schedule so far (not the final ones an interruption adds to its partial file),
/// and the time of the next snapshot due. A resumed run takes exactly these from the
/// interrupted run's file and goes on with the same schedule, so its file is the one an
/// uninterrupted run writes.
struct OutputSchedule {
    std::size_t snapshots = 0;
    std::size_t historyRows = 0;
    double nextSnapshotUs = 0.0;
};

/// Copies the first `schedule.snapshots` snapshots and `schedule.historyRows` history rows of
/// `previous` (an interrupted run's file) into `writer`.
void carryOver(const std::filesystem::path& previousFile, const OutputSchedule& schedule,
               io::RunFileWriter& writer) {
    io::RunFileReader previous(previousFile);
    const std::size_t snapshots = std::min(schedule.snapshots, previous.snapshots().size());
    for (std::size_t k = 0; k < snapshots; ++k) {
        auto snap = previous.readSnapshot(static_cast<int>(k));
        if (snap.fe) {
            const io::FeFieldsView feView = io::viewOf(*snap.fe);
            writer.writeSnapshot(snap.info.timeUs, snap.info.step, io::viewOf(snap.particles),
                                 &feView);
        } else {
            writer.writeSnapshot(snap.info.timeUs, snap.info.step, io::viewOf(snap.particles));
        }
    }
    const io::HistoryColumns h = previous.readHistory();
    for (std::size_t k = 0; k < std::min(schedule.historyRows, h.timeUs.size()); ++k) {
        writer.appendHistory(io::rowOf(h, k));
    }
}

/// The schedule a checkpoint records (checkpoints written before it was recorded: every
/// snapshot and row up to the checkpoint's time, the next snapshot one interval later).
OutputSchedule scheduleOf(const io::CheckpointState& state, const std::filesystem::path& file,
                          double snapshotEvery) {
    const nlohmann::json& s = state.extra;
    if (s.contains("schedule")) {
        return {s["schedule"]["snapshots"].get<std::size_t>(),
                s["schedule"]["history_rows"].get<std::size_t>(),
                s["schedule"]["next_snapshot_us"].get<double>()};
    }
    OutputSchedule o;
    io::RunFileReader previous(file);
    for (const auto& info : previous.snapshots()) {
        if (info.timeUs <= state.timeUs + 1e-12) {
            ++o.snapshots;
            o.nextSnapshotUs = info.timeUs + snapshotEvery;
        }
    }
    for (double t : previous.readHistory().timeUs) {
        o.historyRows += t <= state.timeUs + 1e-12 ? 1 : 0;
    }
    return o;
}

/// What set the last time step: the package, and for SPH the particle, for FE the element
/// (its body, place, density and sound speed: a hot or a crushed element shows as such).
std::string limiterOf(const Simulation& sim) {
    std::string limiter = sim.dtLimiter();
    const auto bodyName = [&](int32_t body) {
        return sim.scene().bodies[static_cast<std::size_t>(body)].name.c_str();
    };
    char buf[200];
    const int32_t lim = sim.dtLimitingParticle();
    if (limiter == "sph" && lim >= 0) {
        const auto& ps = sim.particles();
        std::snprintf(buf, sizeof buf, "sph: %s #%d (z %.3f r %.3f mm)", bodyName(ps.body[lim]),
                      lim, ps.z[lim], ps.r[lim]);
        limiter = buf;
    }
    const fe::FeSolid* fe = sim.finiteElements();
    if (limiter == "fe" && fe && fe->limitingElement() >= 0) {
        const auto i = static_cast<std::size_t>(fe->limitingElement());
        const auto& el = fe->elements();
        const auto& nd = fe->nodes();
        double z = 0.0, r = 0.0;
        for (int a = 0; a < 4; ++a) {
            z += 0.25 * nd.z[static_cast<std::size_t>(el.node(i, a))];
            r += 0.25 * nd.r[static_cast<std::size_t>(el.node(i, a))];
        }
        std::snprintf(buf, sizeof buf, "fe: %s element #%zu (z %.3f r %.3f mm, %.2f g/cm3, c %.1f km/s)",
                      bodyName(el.body[i]), i, z, r, el.rho[i], el.cs[i]);
        limiter = buf;
    }
    return limiter;
}

/// Restores `sim` from its checkpoint and carries the interrupted run's snapshots and history
/// into `writer`; returns the output schedule to go on with.
OutputSchedule resumeFrom(const std::filesystem::path& checkpointPath,
                          const std::string& fingerprint, const std::filesystem::path& runFile,
                          Simulation& sim, RunSummary& summary, io::RunFileWriter& writer,
                          const std::function<void(const std::string&)>& log) {
    OutputSchedule schedule;
    const io::CheckpointState state = io::readCheckpoint(checkpointPath);
    // A checkpoint of another scene with the same point count would restore without a
    // word, and the run file's /scene would describe a run it did not come from.
    if (state.extra.contains("scene_fingerprint") &&
        state.extra["scene_fingerprint"] != fingerprint) {
        throw InputError(checkpointPath.string(), "/extra/scene_fingerprint",
                         "the checkpoint was written by a run of another scene or material "
                         "library (fingerprint " +
                             state.extra["scene_fingerprint"].get<std::string>() + ", this run's " +
                             fingerprint + ")",
                         "--resume with the scene and --materials of the interrupted run, "
                         "or delete the checkpoint to start afresh");
    }
    sim.restore(state);
    // Without the interrupted run's file the new one would start at the checkpoint, and an
    // assessment of it would miss the impact's first microseconds without a word.
    const auto orphan = io::orphanedTemporary(runFile);
    if (!std::filesystem::exists(runFile) && !orphan && sim.time() > 0.0) {
        throw InputError(checkpointPath.string(), "",
                         "the snapshots and history before its t = " + std::to_string(sim.time()) +
                             " us are gone: neither " + runFile.string() + " nor the " +
                             runFile.string() + ".tmp.PID an interrupted run leaves exists",
                         "put the interrupted run's file back, or delete the checkpoint and "
                         "run afresh");
    }
    summary.maxEnergyError = state.extra.value("max_energy_error", 0.0);
    if (state.extra.contains("min_dt")) {
        summary.minDtUs = state.extra["min_dt"]["dt_us"].get<double>();
        summary.minDtTimeUs = state.extra["min_dt"]["time_us"].get<double>();
        summary.minDtLimiter = state.extra["min_dt"]["limiter"].get<std::string>();
    }
    summary.resumed = true;
    summary.earlierWallSeconds =
        state.extra.contains("wall_time_s") ? state.extra["wall_time_s"].get<double>() : NAN;
    // Carry the snapshots and history of the interrupted run into the new file: its run
    // file (stopped by a signal), or the temporary it left when it was killed outright.
    if (std::filesystem::exists(runFile)) {
        schedule = scheduleOf(state, runFile, sim.scene().output.snapshotEvery);
        carryOver(runFile, schedule, writer);
    } else if (orphan) {
        schedule = scheduleOf(state, *orphan, sim.scene().output.snapshotEvery);
        carryOver(*orphan, schedule, writer);
        std::error_code ignored;
        std::filesystem::remove(*orphan, ignored); // all it held is in the new file now
        log("carried the snapshots of " + orphan->string() +
            " (a run killed outright) into the new file");
    }
    log("resumed from " + checkpointPath.string() + " at t = " + std::to_string(sim.time()) +
        " us, step " + std::to_string(sim.step()));
    return schedule;
}

/// The progress line on stderr.
std::string progressLine(const Simulation& sim, double wallSeconds, double startTimeUs) {
    const double endTime = sim.scene().run.endTime;
    const double rate = (sim.time() - startTimeUs) / std::max(wallSeconds, 1e-9);
    const double eta = rate > 0 ? (endTime - sim.time()) / rate : NAN;
    const std::string limiter = limiterOf(sim);
    std::string elements;
    if (const fe::FeSolid* fe = sim.finiteElements()) {
        elements = "  elements " + std::to_string(fe->evaluatedCount()) + " active/" +
                   std::to_string(fe->elements().size()) + " (" +
                   std::to_string(fe->erodedCount()) + " eroded)";
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "t %.4f/%.3f us  dt %.2e us (%s)  particles %zu active/%zu%s  wall %s  "
                  "ETA <= %s  energy error %+.2e",
                  sim.time(), endTime, sim.lastDt(), limiter.c_str(), sim.activeCount(),
                  sim.aliveCount(), elements.c_str(), formatDuration(wallSeconds).c_str(),
                  formatDuration(eta).c_str(), sim.energyError());
    return line;
}

/// The run's facts for the run file's /provenance.
nlohmann::json finalFacts(const Simulation& sim, const RunSummary& summary,
                          const RunOptions& options) {
    const Totals t = sim.totals();
    // A resumed run's wall time is the whole run's (null when a checkpoint of an older build
    // did not record its part).
    auto seconds = [](double s) { return std::isfinite(s) ? nlohmann::json(s) : nlohmann::json(); };
    return {{"wall_time_s", seconds(summary.wholeWallSeconds())},
            {"earlier_wall_time_s", seconds(summary.earlierWallSeconds)},
            {"this_wall_time_s", summary.wallSeconds},
            {"threads", options.threads},
            {"steps", sim.step()},
            {"end_time_us", sim.time()},
            {"particles", summary.particles},
            {"alive_particles", t.alive},
            {"deleted_runaway", sim.runawayDeleted()},
            {"deleted_out_of_domain", sim.outOfDomainDeleted()},
            {"eroded_elements", t.erodedElements},
            {"max_abs_energy_error", summary.maxEnergyError},
            {"particle_spacing_mm", sim.scene().sph.particleSpacing},
            {"resumed", summary.resumed},
            {"min_dt_us", std::isfinite(summary.minDtUs) ? nlohmann::json(summary.minDtUs)
                                                         : nlohmann::json(nullptr)},
            {"min_dt_time_us", summary.minDtTimeUs},
            {"min_dt_limiter", summary.minDtLimiter},
            {"particle_steps_per_s", summary.particleSteps / std::max(summary.wallSeconds, 1e-9)}};
}

} // namespace

RunSummary runToCompletion(Simulation& sim, const std::string& sceneText,
                           const std::string& materialsText, const nlohmann::json& provenance,
                           const RunOptions& options,
                           const std::function<void(const std::string&)>& log) {
    const scene::Scene& scene = sim.scene();
    const auto t0 = Clock::now();
    sim.resetTimes();
    RunSummary summary;
    summary.particles = sim.particles().size();
    const auto checkpointPath = io::checkpointPathFor(options.runFile);

    const std::string fingerprint = sceneFingerprint(sceneText, materialsText);
    OutputSchedule schedule; // what has been written on schedule
    auto checkpointNow = [&]() {
        io::CheckpointState state = checkpointOf(sim, summary.maxEnergyError);
        state.extra["scene_fingerprint"] = fingerprint;
        if (std::isfinite(summary.earlierWallSeconds)) {
            state.extra["wall_time_s"] = summary.earlierWallSeconds + secondsSince(t0);
        }
        if (std::isfinite(summary.minDtUs)) { // none before the first step
            state.extra["min_dt"] = {{"dt_us", summary.minDtUs},
                                     {"time_us", summary.minDtTimeUs},
                                     {"limiter", summary.minDtLimiter}};
        }
        state.extra["schedule"] = {{"snapshots", schedule.snapshots},
                                   {"history_rows", schedule.historyRows},
                                   {"next_snapshot_us", schedule.nextSnapshotUs}};
        io::writeCheckpoint(checkpointPath, state);
    };
    io::RunFileWriter writer(options.runFile, sceneText, materialsText, provenance);
    if (options.resume && std::filesystem::exists(checkpointPath)) {
        schedule =
            resumeFrom(checkpointPath, fingerprint, options.runFile, sim, summary, writer, log);
    }

    std::vector<double> deviator;
    long lastSnapshotStep = -1, lastRecordStep = -1;
    double outputSeconds = 0.0;
    auto snapshot = [&]() {
        const Stopwatch watch;
        if (const fe::FeSolid* fe = sim.finiteElements()) {
            const std::vector<double> erosionStrain = fe->erosionStrain();
            const io::FeFieldsView feView = feFieldsOf(*fe, erosionStrain);
            writer.writeSnapshot(sim.time(), sim.step(),
                                 particleFieldsOf(sim.particles(), deviator), &feView);
        } else {
            writer.writeSnapshot(sim.time(), sim.step(),
                                 particleFieldsOf(sim.particles(), deviator));
        }
        lastSnapshotStep = sim.step();
        outputSeconds += watch.seconds();
    };
    auto record = [&]() {
        const Stopwatch watch;
        const io::HistoryRow row = historyRow(sim);
        summary.maxEnergyError = std::max(summary.maxEnergyError, std::fabs(row.energyError));
        writer.appendHistory(row);
        lastRecordStep = sim.step();
        outputSeconds += watch.seconds();
    };
    if (!summary.resumed) {
        snapshot();
        record();
        schedule = {1, 1, scene.output.snapshotEvery};
    }
    auto lastProgress = Clock::now();
    auto lastCheckpoint = Clock::now();
    const long startStep = sim.step();
    const double startTime = sim.time();
    std::optional<std::string> reason;
    while (!(reason = sim.stopReason())) {
        if (g_stopRequested.load()) {
            break;
        }
        sim.advance();
        summary.profile.steps.add(sim.lastDt(), sim.dtLimiter());
        if (sim.lastDt() < summary.minDtUs) { // the smallest step, and what set it
            summary.minDtUs = sim.lastDt();
            summary.minDtTimeUs = sim.time();
            summary.minDtLimiter = limiterOf(sim);
        }
        summary.particleSteps += static_cast<double>(sim.aliveCount());
        summary.activeParticleSteps += static_cast<double>(sim.activeCount());
        if (const fe::FeSolid* fe = sim.finiteElements()) {
            summary.elementSteps += static_cast<double>(fe->evaluatedCount());
        }
        if (sim.step() % scene.output.historyEverySteps == 0) {
            record();
            ++schedule.historyRows;
        }
        if (sim.time() >= schedule.nextSnapshotUs - 1e-12) {
            snapshot();
            ++schedule.snapshots;
            schedule.nextSnapshotUs += scene.output.snapshotEvery;
        }
        if (!options.quiet && secondsSince(lastProgress) >= 1.0) {
            lastProgress = Clock::now();
            log(progressLine(sim, secondsSince(t0), startTime));
        }
        if (options.checkpointEverySeconds > 0 &&
            secondsSince(lastCheckpoint) >= options.checkpointEverySeconds) {
            const Stopwatch watch;
            writer.flush();
            checkpointNow();
            outputSeconds += watch.seconds();
            lastCheckpoint = Clock::now();
        }
    }
    summary.steps = sim.step() - startStep;
    summary.timeUs = sim.time();
    summary.wallSeconds = secondsSince(t0);
    if (!reason) {
        checkpointNow(); // before the final row and snapshot below, which are off schedule
    }
    // The final state, unless it was just written.
    if (lastRecordStep != sim.step()) {
        record();
    }
    if (lastSnapshotStep != sim.step()) {
        snapshot();
    }
    summary.profile.packages = sim.packageTimes();
    summary.profile.binned = sim.binnedWork();
    summary.profile.loop = {{"deletion", sim.deletionSeconds()},
                            {"stop rules", sim.stopRuleSeconds()},
                            {"output", outputSeconds}};
    summary.profile.wallSeconds = secondsSince(t0);
    nlohmann::json facts = finalFacts(sim, summary, options);
    facts["profile"] = profileJson(summary.profile);
    if (reason) {
        summary.stopReason = *reason;
        summary.complete = true;
        facts["stop_reason"] = *reason;
        writer.finish(facts);
        std::error_code ignored;
        std::filesystem::remove(checkpointPath, ignored);
    } else {
        summary.stopReason = "interrupted";
        facts["stop_reason"] = "interrupted";
        writer.abandon(facts);
        log("interrupted at t = " + std::to_string(sim.time()) + " us; checkpoint " +
            checkpointPath.string() + " (continue with --resume)");
    }
    return summary;
}

} // namespace hvi::solver
