// Drives a Simulation to its stop rule and records it: snapshots and histories in the run
// file, a progress line on stderr about once a second (simulated time, dt, particles, wall
// time, ETA, energy error), checkpoints every few minutes of wall time and on an interrupt,
// and resuming from a checkpoint.
#pragma once

#include "io/Checkpoint.hpp"
#include "io/RunFileWriter.hpp"
#include "solver/Profile.hpp"
#include "solver/Simulation.hpp"

#include <atomic>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace hvi::solver {

/// Set by a signal handler to ask the loop to stop at the end of the current step.
extern std::atomic<bool> g_stopRequested;

struct RunOptions {
    std::string runFile; ///< the HDF5 run file to write
    int threads = 1;
    bool quiet = false;
    double checkpointEverySeconds = 300; ///< wall time between checkpoints (0 = never)
    bool resume = false;                 ///< continue from RUN.ckpt.h5 if present
};

struct RunSummary {
    std::string stopReason;
    bool complete = false;    ///< false when interrupted
    double wallSeconds = 0.0; ///< this invocation's, from its start or resume
    /// The wall time the run had taken up to the checkpoint it resumed from (0 for a run made
    /// straight through; NaN when that checkpoint did not record it). Work done after that
    /// checkpoint and lost to the interruption is not counted: it is done again here.
    double earlierWallSeconds = 0.0;
    /// The whole run's wall time: the earlier parts' and this one (NaN when not recorded).
    double wholeWallSeconds() const { return earlierWallSeconds + wallSeconds; }
    long steps = 0;
    double timeUs = 0.0;
    double maxEnergyError = 0.0; ///< max |energy error| over the history rows
    double particleSteps = 0.0;  ///< sum over steps of alive particles
    double activeParticleSteps = 0.0;
    double elementSteps = 0.0; ///< sum over steps of FE elements evaluated
    /// The smallest time step [us], when it was taken [us] and what set it.
    double minDtUs = std::numeric_limits<double>::infinity();
    double minDtTimeUs = 0.0;
    std::string minDtLimiter;
    std::size_t particles = 0;
    bool resumed = false;
    /// Where the wall time went and the steps taken (since the start or the resume).
    RunProfile profile;
};

/// Runs `sim` to a stop rule. `provenance` goes into the run file. `log` receives progress
/// and information lines (already prefixed by the caller's tool name if it wants).
RunSummary runToCompletion(Simulation& sim, const std::string& sceneText,
                           const std::string& materialsText, const nlohmann::json& provenance,
                           const RunOptions& options,
                           const std::function<void(const std::string&)>& log);

/// The simulation's checkpoint (Simulation::save) with the run's largest energy error so far;
/// Simulation::restore reads it back.
io::CheckpointState checkpointOf(const Simulation& sim, double maxEnergyError);

} // namespace hvi::solver
