// What the fuzz targets share (libFuzzer, clang's -fsanitize=fuzzer; scripts/fuzz.sh builds and
// runs them). Each target hands its input to a tool the way a user would, as a file on disk,
// and runs the tool in-process through the same Tool::run as its executable. A crash, a
// sanitizer report, a hang (libFuzzer's -timeout) or an exception outside the error contract
// (reported as "internal error") is a finding; exit codes 2 and 3 with their one line are the
// contract working.
#pragma once

#include "tool/Tool.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace hvi::fuzz {

/// A scratch directory of this process (under TMPDIR), made on first use and removed when
/// the process exits normally (libFuzzer's -runs and -max_total_time end through exit()).
/// The path is never destroyed, so the exit handler can still read it.
inline const std::filesystem::path& scratch() {
    static const std::filesystem::path* const dir = [] {
        const char* tmp = std::getenv("TMPDIR");
        auto* d = new std::filesystem::path(std::filesystem::path(tmp && *tmp ? tmp : "/tmp") /
                                            ("hvi-fuzz-" + std::to_string(::getpid())));
        std::filesystem::create_directories(*d);
        std::atexit([] {
            std::error_code ignored;
            std::filesystem::remove_all(scratch(), ignored);
        });
        return d;
    }();
    return *dir;
}

/// Writes the input to scratch()/name and returns its path.
inline std::filesystem::path writeInput(const uint8_t* data, size_t size, const std::string& name) {
    const auto path = scratch() / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

/// Runs `tool` with `args` (argv[0] first) with std::cout and std::cerr captured; aborts,
/// printing what the tool said, when it ended on an internal error. `said` receives stderr.
inline int runCaptured(tool::Tool& tool, std::vector<std::string> args,
                       std::string* said = nullptr) {
    std::vector<char*> argv;
    for (auto& a : args) {
        argv.push_back(a.data());
    }
    std::ostringstream out, err;
    auto* coutBuf = std::cout.rdbuf(out.rdbuf());
    auto* cerrBuf = std::cerr.rdbuf(err.rdbuf());
    const int code = tool.run(static_cast<int>(argv.size()), argv.data());
    std::cout.rdbuf(coutBuf);
    std::cerr.rdbuf(cerrBuf);
    if (said) {
        *said = err.str();
    }
    if (tool.endedOnInternalError()) {
        std::fprintf(stderr, "fuzz: %s ended on an internal error:\n%s\n", args[0].c_str(),
                     err.str().c_str());
        std::abort();
    }
    return code;
}

} // namespace hvi::fuzz
