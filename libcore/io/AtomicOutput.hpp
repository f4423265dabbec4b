// Outputs appear whole or not at all: a tool writes to "NAME.tmp.PID" and renames it to
// NAME only when everything succeeded. A tool that throws leaves nothing behind, because
// the destructor removes an uncommitted temporary.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace hvi::io {

class AtomicOutput {
public:
    /// `finalPath` "-" means standard output (written directly at commit time).
    explicit AtomicOutput(std::filesystem::path finalPath);
    ~AtomicOutput();
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;

    /// Where to write (a temporary beside the final file).
    const std::filesystem::path& tempPath() const { return m_tempPath; }
    const std::filesystem::path& finalPath() const { return m_finalPath; }
    bool isStdout() const { return m_finalPath == "-"; }

    /// Renames the temporary onto the final path (or copies it to stdout).
    void commit();

private:
    std::filesystem::path m_finalPath;
    std::filesystem::path m_tempPath;
    bool m_committed = false;
};

/// The temporary that a writer of `finalPath` killed outright (SIGKILL, power loss) left
/// behind: a NAME.tmp.PID beside it whose process no longer runs; the newest if several,
/// nullopt if none. A PID that another process has taken since counts as running, so a
/// temporary is never taken from a writer that may still be alive.
std::optional<std::filesystem::path> orphanedTemporary(const std::filesystem::path& finalPath);

/// Writes `text` to `path` atomically ("-" = stdout). Throws RuntimeFailure on I/O error.
void writeTextAtomically(const std::filesystem::path& path, const std::string& text);

} // namespace hvi::io
