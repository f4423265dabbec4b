// Restart state of a run: a small HDF5 file NAME.ckpt.h5 beside the run file, written
// atomically (NAME.ckpt.h5.tmp.PID, then rename), so a checkpoint on disk is always a whole
// one: a kill during the write leaves the previous checkpoint in place.
//
// The solver calls writeCheckpoint every N seconds of wall time and when it notices SIGINT
// (never from inside the signal handler), and readCheckpoint on --resume. The state is
// generic -- named arrays plus JSON -- so the solver's storage can change without touching
// this module; the solver is responsible for what it puts in and for checking, on resume,
// that the checkpoint belongs to the same scene (e.g. a scene hash in `extra`).
//
// Layout:
//   /                  @Format = "hvi-checkpoint", @FormatVersion = 1, @Time [us], @Step
//   /doubles/<name>    1-D float64, one per entry of CheckpointState::doubles
//   /ints/<name>       1-D int32, one per entry of CheckpointState::ints
//   /extra             JSON text (counters, snapshot index, scene hash, provenance, ...)
// Doubles are stored bit for bit: a resumed run continues exactly where it stopped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hvi::io {

inline constexpr int kCheckpointFormatVersion = 1;

struct CheckpointState {
    double timeUs = 0.0;
    long step = 0;
    std::map<std::string, std::vector<double>> doubles; ///< e.g. "z", "vz", "stress_deviator"
    std::map<std::string, std::vector<int32_t>> ints;   ///< e.g. "body_id", "alive"
    nlohmann::json extra = nlohmann::json::object();    ///< counters and anything else
};

/// Writes `state` to `path` atomically, replacing an older checkpoint. Array names must be
/// non-empty and contain no '/'. Throws RuntimeFailure (bad name, HDF5 or rename error);
/// then the previous checkpoint, if any, is untouched.
void writeCheckpoint(const std::filesystem::path& path, const CheckpointState& state);

/// Reads a checkpoint. Throws InputError naming the file and the HDF5 path of what is
/// missing or unreadable (or "/" for a file that is not an HDF5 checkpoint).
CheckpointState readCheckpoint(const std::filesystem::path& path);

/// The checkpoint path of a run file: run.h5 -> run.ckpt.h5.
std::filesystem::path checkpointPathFor(const std::filesystem::path& runFile);

} // namespace hvi::io
