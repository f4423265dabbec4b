#include "io/AtomicOutput.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <fstream>
#include <iostream>
#include <system_error>
#include <unistd.h>

namespace hvi::io {

namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(fs::path finalPath) : m_finalPath(std::move(finalPath)) {
    if (isStdout()) {
        m_tempPath = fs::temp_directory_path() /
                     ("hvi-stdout.tmp." + std::to_string(static_cast<long>(::getpid())));
    } else {
        m_tempPath = m_finalPath;
        m_tempPath += ".tmp." + std::to_string(static_cast<long>(::getpid()));
        const fs::path parent = m_finalPath.parent_path();
        if (!parent.empty() && !fs::is_directory(parent)) {
            throw RuntimeFailure("cannot write " + m_finalPath.string() + ": directory " +
                                 parent.string() + " does not exist");
        }
    }
}

AtomicOutput::~AtomicOutput() {
    if (!m_committed) {
        std::error_code ignored;
        fs::remove(m_tempPath, ignored);
    }
}

void AtomicOutput::commit() {
    if (isStdout()) {
        std::ifstream in(m_tempPath, std::ios::binary);
        std::cout << in.rdbuf();
        std::cout.flush();
        std::error_code ignored;
        fs::remove(m_tempPath, ignored);
    } else {
        std::error_code ec;
        fs::rename(m_tempPath, m_finalPath, ec);
        if (ec) {
            throw RuntimeFailure("cannot move " + m_tempPath.string() + " to " +
                                 m_finalPath.string() + ": " + ec.message());
        }
    }
    m_committed = true;
}

std::optional<fs::path> orphanedTemporary(const fs::path& finalPath) {
    const fs::path dir = finalPath.parent_path().empty() ? fs::path(".") : finalPath.parent_path();
    const std::string prefix = finalPath.filename().string() + ".tmp.";
    std::optional<fs::path> newest;
    fs::file_time_type newestTime{};
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const std::string pid = name.substr(std::min(prefix.size(), name.size()));
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            pid.size() > 9 ||
            !std::all_of(pid.begin(), pid.end(), [](unsigned char c) { return std::isdigit(c); })) {
            continue;
        }
        const auto id = static_cast<pid_t>(std::stol(pid));
        if (id == ::getpid() || ::kill(id, 0) == 0 || errno != ESRCH) {
            continue; // its writer runs (or may: not ours to signal)
        }
        std::error_code timeError;
        const auto when = fs::last_write_time(it->path(), timeError);
        if (!timeError && (!newest || when > newestTime)) {
            newest = it->path();
            newestTime = when;
        }
    }
    return newest;
}

void writeTextAtomically(const fs::path& path, const std::string& text) {
    AtomicOutput output(path);
    {
        std::ofstream out(output.tempPath(), std::ios::binary);
        out << text;
        out.flush();
        if (!out) {
            throw RuntimeFailure("cannot write " + output.tempPath().string());
        }
    }
    output.commit();
}

} // namespace hvi::io
