#include "io/RunLock.hpp"

#include "core/Error.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <unistd.h>

namespace hvi::io {

std::filesystem::path lockPathFor(const std::filesystem::path& runFile) {
    return std::filesystem::path(runFile).replace_extension(".lock");
}

RunLock::RunLock(const std::filesystem::path& runFile) : m_path(lockPathFor(runFile)) {
    m_fd = ::open(m_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (m_fd < 0) {
        throw RuntimeFailure("cannot create the lock " + m_path.string() + ": " +
                             std::strerror(errno));
    }
    if (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        ::close(m_fd);
        m_fd = -1;
        if (error == EWOULDBLOCK) {
            throw InputError("<flags>", "--output",
                             "another hvi-run is writing " + runFile.string() + " (it holds " +
                                 m_path.string() + ")",
                             "another -o, or wait for that run to end");
        }
        throw RuntimeFailure("cannot lock " + m_path.string() + ": " + std::strerror(error));
    }
    const std::string pid = std::to_string(static_cast<long>(::getpid())) + "\n";
    if (::ftruncate(m_fd, 0) == 0) {
        [[maybe_unused]] const auto written = ::write(m_fd, pid.data(), pid.size());
    }
}

RunLock::~RunLock() {
    if (m_fd >= 0) {
        ::unlink(m_path.c_str()); // while still held: no one can take a lock we then remove
        ::close(m_fd);
    }
}

} // namespace hvi::io
