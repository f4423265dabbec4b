// One writer per run file: hvi-run holds an exclusive lock on RUN.lock (flock(2)) from before
// it reads its scene until it exits. A second hvi-run on the same -o is refused instead of
// both running and the last rename silently winning, with the other's mesh and checkpoint
// beside it (issue #25, item 13). The kernel drops the lock when the holder dies, however it
// dies, so a killed run never leaves a stale lock; the file is removed on a normal exit.
#pragma once

#include <filesystem>

namespace hvi::io {

class RunLock {
public:
    /// Takes the lock of `runFile`; throws InputError (<flags>, --output) when another
    /// process holds it, RuntimeFailure when the lock file cannot be created.
    explicit RunLock(const std::filesystem::path& runFile);
    ~RunLock();
    RunLock(const RunLock&) = delete;
    RunLock& operator=(const RunLock&) = delete;

    const std::filesystem::path& path() const { return m_path; }

private:
    std::filesystem::path m_path;
    int m_fd = -1;
};

/// RUN.lock for RUN.h5 (beside it, the run's extension replaced).
std::filesystem::path lockPathFor(const std::filesystem::path& runFile);

} // namespace hvi::io
