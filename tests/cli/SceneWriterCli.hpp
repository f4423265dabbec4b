// Helpers for the scene writers' CLI tests (foam2layers_test.cpp, hcomb2rings_test.cpp):
// run a built tool, capture exit code, stdout and stderr; read and check its scene.
#pragma once

#include "TestPaths.hpp"
#include "io/JsonInput.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace hvi::test {

struct ToolRun {
    int exitCode = -1;
    std::string out;
    std::string err;

    /// stderr split into lines (without the newlines).
    std::vector<std::string> errLines() const {
        std::vector<std::string> lines;
        std::istringstream in(err);
        for (std::string line; std::getline(in, line);) {
            lines.push_back(line);
        }
        return lines;
    }
};

inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline std::string shellQuote(const std::string& arg) {
    std::string quoted = "'";
    for (char c : arg) {
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return quoted + "'";
}

/// Runs `tool` with `args`; `tag` names the capture files (unique per test).
inline ToolRun runTool(const std::string& tool, const std::vector<std::string>& args,
                       const std::string& tag) {
    const auto outPath = tempPath(tag + ".stdout");
    const auto errPath = tempPath(tag + ".stderr");
    std::string command = shellQuote(toolPath(tool).string());
    for (const auto& arg : args) {
        command += " " + shellQuote(arg);
    }
    command += " > " + shellQuote(outPath.string()) + " 2> " + shellQuote(errPath.string()) +
               " < /dev/null";
    const int status = std::system(command.c_str());
    ToolRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = readText(outPath);
    run.err = readText(errPath);
    return run;
}

/// A fresh output path: removed first, so that "it does not exist afterwards" means something.
inline std::filesystem::path freshOutput(const std::string& name) {
    const auto path = tempPath(name);
    std::filesystem::remove(path);
    return path;
}

inline nlohmann::json readJson(const std::filesystem::path& path) {
    return nlohmann::json::parse(readText(path));
}

/// Validates a scene against schemas/scene.schema.json; the failure message lists the issues.
inline ::testing::AssertionResult validScene(const nlohmann::json& scene) {
    try {
        io::validateAgainstSchema(scene, "scene", "scene");
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << e.what();
    }
    return ::testing::AssertionSuccess();
}

/// The bodies of a scene with the given role, in file order.
inline std::vector<nlohmann::json> bodiesWithRole(const nlohmann::json& scene,
                                                  const std::string& role) {
    std::vector<nlohmann::json> out;
    for (const auto& body : scene.at("bodies")) {
        if (body.at("role") == role) {
            out.push_back(body);
        }
    }
    return out;
}

/// The one-line error form of docs/conventions.md, `tool: FILE: /pointer: problem (expected)`,
/// checked for exactly one line naming `file` and `pointer`.
inline ::testing::AssertionResult oneErrorLine(const ToolRun& run, const std::string& tool,
                                               const std::string& file,
                                               const std::string& pointer) {
    const auto lines = run.errLines();
    if (lines.size() != 1) {
        return ::testing::AssertionFailure()
               << "expected one stderr line, got " << lines.size() << ":\n"
               << run.err;
    }
    static const std::regex form(R"(^([^:]+): (.+?): (/[^ ]*): (.+) \((.+)\)$)");
    std::smatch match;
    if (!std::regex_match(lines[0], match, form)) {
        return ::testing::AssertionFailure()
               << "not 'tool: FILE: /pointer: problem (expected)': " << lines[0];
    }
    if (match[1] != tool || match[2] != file || match[3] != pointer) {
        return ::testing::AssertionFailure() << "expected tool '" << tool << "', file '" << file
                                             << "', pointer '" << pointer << "' in: " << lines[0];
    }
    return ::testing::AssertionSuccess();
}

/// The element count of a MSH 4.1 file ("$Elements" then "numBlocks numElements ...").
inline long mshElementCount(const std::filesystem::path& path) {
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line == "$Elements") {
            long blocks = 0;
            long elements = -1;
            in >> blocks >> elements;
            return elements;
        }
    }
    return -1;
}

} // namespace hvi::test
