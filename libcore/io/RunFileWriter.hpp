// Writes the HDF5 run file of one hvi-run simulation (STYLE practice 7, after SWIFT): the
// scene and materials it ran, provenance, units, snapshots of particle and finite-element
// state, the time history and the run facts; plus the XDMF sidecar for ParaView.
//
// Layout (every dataset carries `Units`, `Description`, `CgsConversionFactor` and the
// SWIFT-style `U_L exponent`, `U_M exponent`, `U_t exponent` attributes):
//
//   /                      @Format = "hvi-run", @FormatVersion = 2
//   /scene                 scene JSON text (the resolved input the run used)
//   /materials             materials JSON text
//   /provenance            the provenance JSON text given to the constructor
//   /Code                  @tool @version @git @compiler @build_type @threads @hdf5_version ...
//   /Units                 @length "mm" @mass "mg" @time "us" ... and SWIFT's
//                          @"Unit length in cgs (U_L)" = 0.1, (U_M) = 1e-3, (U_t) = 1e-6 ...
//   /snapshots/000000      @Time [us] @Step @ParticleCount (@NodeCount @ElementCount)
//       Z R Vz Vr Mass ... (one dataset per particle field of OutputFields.hpp)
//       Nodes/Z R Vz Vr Mass                          (finite-element bodies only)
//       Elements/Connectivity Alive ... BodyId        (finite-element bodies only)
//       View/Particles/ View/FiniteElements/          the live material in ParaView's
//                                                     shapes, for the sidecar (RunFileView.hpp)
//   /snapshots/000001 ...
//   /history/Time Dt Step KineticEnergy ...           1-D, one value per appended row
//   /run                   @status "complete" | "partial", @stop_reason, @wall_time_s, ...
//
// Atomicity (docs/conventions.md, "Outputs"): the file is written as NAME.tmp.PID and renamed
// onto NAME by finish(). A writer destroyed without finish() or abandon() -- the run threw --
// deletes the temporary: a failed run leaves no run file.
//
// Interrupted runs: abandon() is for a run stopped by the user (SIGINT/SIGTERM noticed by
// the time loop). It keeps what was computed, under the final name, with /run@status
// "partial". Choice: an interruption is not a failure -- every snapshot in the file is
// valid, an engineer can assess the run so far (hvi-assess reads /run@status and says
// "partial"), and the run can be resumed from its checkpoint. A run that *fails* (blow-up,
// write error) throws instead and leaves nothing. A run killed outright (SIGKILL, power
// loss) leaves NAME.tmp.PID, readable up to the last flush() (the reader opens it; it just
// has no /run group); a resumed run takes its snapshots up to the checkpoint from it
// (io::orphanedTemporary) and removes it.
//
// Not thread-safe; call from the solver's main thread, outside OpenMP parallel regions.
#pragma once

#include "io/OutputFields.hpp"

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace hvi::io {

/// Version of the layout above; the reader refuses files from a newer version.
inline constexpr int kRunFileFormatVersion = 2;

struct RunFileWriterOptions {
    /// 0: no compression (the default: writing speed matters more than size for snapshots
    /// of a few hundred thousand particles); 1-9: shuffle + gzip at that level, chunked.
    int gzipLevel = 0;
    /// H5Fflush after every snapshot, so a run killed outright still leaves a readable
    /// temporary file up to its last snapshot (cheap next to the snapshot itself).
    bool flushEachSnapshot = true;
};

class RunFileWriter {
public:
    /// Creates `finalPath`'s temporary (NAME.tmp.PID) and writes /scene, /materials,
    /// /provenance, /Code (from `provenance`: tool, version, git, compiler, threads...;
    /// missing version/git/compiler/build_type are filled from this build) and /Units.
    /// Throws RuntimeFailure when the file cannot be created (missing directory, no space).
    RunFileWriter(std::filesystem::path finalPath, const std::string& sceneJson,
                  const std::string& materialsJson, const nlohmann::json& provenance,
                  RunFileWriterOptions options = {});
    /// Without finish()/abandon(): closes and deletes the temporary.
    ~RunFileWriter();
    RunFileWriter(const RunFileWriter&) = delete;
    RunFileWriter& operator=(const RunFileWriter&) = delete;

    /// Writes /snapshots/NNNNNN (sequential from 000000) and returns its index. Every
    /// particle field must hold particles.z.size() * components values; an optional field
    /// may instead be empty (then it is not written). `fe`, when given, must be consistent
    /// the same way (nodes by nodes.z.size(), elements by connectivity.size() / 4, node
    /// indices in range). Throws RuntimeFailure on inconsistent sizes (nothing written) or
    /// on an HDF5 error. The spans are only read during the call.
    int writeSnapshot(double timeUs, long step, const ParticleFieldsView& particles,
                      const FeFieldsView* fe = nullptr);

    /// Buffers one history row; rows reach /history at flush(), finish(), abandon(), or
    /// when the buffer holds kHistoryBatchRows rows.
    void appendHistory(const HistoryRow& row);

    /// Writes buffered history rows and H5Fflush-es the file (call at checkpoints).
    void flush();

    /// Ends a run that stopped normally: writes /run from the flat JSON object `runFacts`
    /// (wall_time_s, threads, stop_reason, steps, ...; @status defaults to "complete"; also
    /// @snapshot_count and @history_rows), writes the history, closes the file, renames it
    /// onto the final path and writes the XDMF sidecar (atomically too). Scalars become
    /// typed attributes; arrays and objects are stored as their JSON text.
    void finish(const nlohmann::json& runFacts);

    /// Ends an interrupted run: as finish(), but @status is "partial" and @stop_reason
    /// defaults to "interrupted". See the file comment for why the file is kept.
    void abandon(const nlohmann::json& runFacts);

    const std::filesystem::path& finalPath() const;
    /// Where the file is while the run is in progress (NAME.tmp.PID).
    const std::filesystem::path& tempPath() const;
    int snapshotCount() const;
    bool isOpen() const;

    static constexpr std::size_t kHistoryBatchRows = 4096;

private:
    struct Impl;
    void close(nlohmann::json runFacts);
    std::unique_ptr<Impl> m_impl;
};

/// The XDMF sidecar path of a run file: run.h5 -> run.xmf.
std::filesystem::path xdmfPathFor(const std::filesystem::path& runFile);

} // namespace hvi::io
