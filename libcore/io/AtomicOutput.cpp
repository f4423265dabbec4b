#include "io/AtomicOutput.hpp"

#include "core/Error.hpp"

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
