// Reads an hvi-run run file (layout: RunFileWriter.hpp) for hvi-assess, for resuming a run,
// and for tests.
//
// Every problem with the file is an InputError whose pointer is the HDF5 path of what is
// wrong, so a tool prints for instance
//   hvi-assess: run.h5: /snapshots/000003/Density: missing (particle field, 1200 values [g/cm3])
//   hvi-assess: notes.txt: /: not an HDF5 file (an HDF5 run file written by hvi-run)
// Opening checks the file is HDF5, complete enough to open, an hvi-run file of a supported
// format version, and lists the snapshots (attributes only); fields are read on demand, so a
// damaged dataset is reported when it is read.
//
// A file from a run that was killed outright (the NAME.tmp.PID it leaves) opens too: it has
// every snapshot flushed before the kill but no /run group (runFacts() then throws;
// hasRunFacts() says so first).
#pragma once

#include "core/Error.hpp"
#include "io/OutputFields.hpp"
#include "io/RunFileXdmf.hpp"

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace hvi::io {

/// One snapshot as listed at open time.
struct SnapshotInfo {
    int index = 0;     ///< NNNNNN of /snapshots/NNNNNN
    std::string group; ///< "/snapshots/000003"
    double timeUs = 0.0;
    long step = 0;
    std::size_t particleCount = 0;
    bool hasFe = false;
    std::size_t nodeCount = 0;
    std::size_t elementCount = 0;
};

/// One snapshot's data. Optional fields absent from the file are empty vectors.
struct Snapshot {
    SnapshotInfo info;
    ParticleFields particles;
    std::optional<FeFields> fe;
};

class RunFileReader {
public:
    /// Opens `path` read-only. Throws InputError (pointer "/" or the missing path) when the
    /// file is missing, not HDF5, truncated, not a run file, or from a newer format.
    explicit RunFileReader(std::filesystem::path path);
    ~RunFileReader();
    RunFileReader(RunFileReader&&) noexcept;
    RunFileReader& operator=(RunFileReader&&) noexcept;
    RunFileReader(const RunFileReader&) = delete;
    RunFileReader& operator=(const RunFileReader&) = delete;

    const std::filesystem::path& path() const;

    /// The snapshots in index (= time) order.
    const std::vector<SnapshotInfo>& snapshots() const;

    /// Reads snapshot /snapshots/NNNNNN with NNNNNN = `index`: every particle field, and the
    /// node and element fields when it has a mesh. Throws InputError naming the dataset that
    /// is missing, has the wrong shape, or cannot be read.
    Snapshot readSnapshot(int index) const;

    /// The /history columns, all the same length.
    HistoryColumns readHistory() const;

    /// The /run attributes as a flat JSON object (status, stop_reason, wall_time_s, ...).
    nlohmann::json runFacts() const;
    bool hasRunFacts() const;

    std::string sceneText() const;
    nlohmann::json scene() const; ///< parsed; InputError at "/scene" if it is not JSON
    std::string materialsText() const;
    nlohmann::json materials() const;
    nlohmann::json provenance() const;
    nlohmann::json code() const;  ///< /Code attributes
    nlohmann::json units() const; ///< /Units attributes

    /// Which datasets each snapshot holds (to rewrite the XDMF sidecar of a recovered file).
    std::vector<SnapshotLayout> layout() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace hvi::io
