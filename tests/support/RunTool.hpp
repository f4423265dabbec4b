// Runs a built tool the way a shell would and captures what it says: the exit code, stdout
// and stderr. For the CLI tests (argument wiring, exit codes, messages, outputs).
#pragma once

#include "TestPaths.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace hvi::test {

struct ToolResult {
    int exitCode = -1;
    std::string out, err;
};

/// Runs `toolPath(tool) args` through /bin/sh; `args` is already shell-quoted.
inline ToolResult runTool(const std::string& tool, const std::string& args,
                          const std::string& stdinText = "") {
    static int counter = 0;
    const auto tag = std::to_string(::getpid()) + "-" + std::to_string(counter++);
    const auto outPath = tempPath("run-" + tag + ".out");
    const auto errPath = tempPath("run-" + tag + ".err");
    std::string command =
        toolPath(tool).string() + " " + args + " >" + outPath.string() + " 2>" + errPath.string();
    if (!stdinText.empty()) {
        const auto inPath = tempPath("run-" + tag + ".in");
        std::ofstream(inPath) << stdinText;
        command += " <" + inPath.string();
    } else {
        command += " </dev/null";
    }
    const int status = std::system(command.c_str());
    ToolResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    auto slurp = [](const std::filesystem::path& p) {
        std::ifstream in(p);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    result.out = slurp(outPath);
    result.err = slurp(errPath);
    std::filesystem::remove(outPath);
    std::filesystem::remove(errPath);
    return result;
}

/// The whole text of a file ("" when it cannot be read).
inline std::string readFileText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Writes `text` to a fresh temporary file and returns its path.
inline std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
    const auto path = tempPath(name);
    std::ofstream(path) << text;
    return path;
}

} // namespace hvi::test
