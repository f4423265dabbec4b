// The one skeleton every executable is built on (after PDAL's Kernel): it sets up the
// command line, the common flags (--help, --version, --quiet, --print-schema), refuses NaN
// and infinities in every numeric flag (FiniteFlags), calls the tool's execute() inside the
// single try/catch, and maps what it throws onto the exit codes of docs/conventions.md. A
// tool's main.cpp is then only
//
//     int main(int argc, char** argv) { return hvi::tool::BleSizeTool().run(argc, argv); }
#pragma once

#include "core/Error.hpp"
#include "tool/FiniteFlags.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

namespace hvi::tool {

class Tool {
public:
    Tool(std::string name, std::string summary);
    virtual ~Tool() = default;
    Tool(const Tool&) = delete;
    Tool& operator=(const Tool&) = delete;

    /// Parses argv, runs, and returns the process exit code. Never throws.
    int run(int argc, char** argv);
    /// Whether the last run() ended on an exception outside the error contract (reported as
    /// "internal error", exit 3): a defect, which the fuzz targets treat as a crash.
    bool endedOnInternalError() const { return m_internalError; }

protected:
    /// Declare the tool's own options (with units and ranges in their help text).
    virtual void addOptions(CLI::App& app) = 0;
    /// Do the work. Throw InputError for bad input, RuntimeFailure for failed computations.
    virtual void execute() = 0;
    /// The embedded schema name of the tool's input file ("" when it has none).
    virtual std::string inputSchemaName() const { return ""; }

    const std::string& name() const { return m_name; }
    bool quiet() const { return m_quiet; }
    /// "tool: warning: message" on stderr (always shown: warnings are never silent).
    void warn(const std::string& message) const;
    /// "tool: message" on stderr unless --quiet.
    void info(const std::string& message) const;
    /// Marks a requested check as failed (hvi-assess --expect): execute() still finishes
    /// and writes its outputs, and run() then returns ExitCode::CheckFailed (1).
    void setCheckFailed() { m_checkFailed = true; }
    /// Tells the NaN/infinity check of the numeric flags (FiniteFlags) that `option` sets
    /// the input document's value at `pointer`, so its error names that pointer.
    void flagSetsPointer(const CLI::Option* option, const std::string& pointer) {
        m_finiteFlags.setPointer(option, pointer);
    }

    /// The provenance block every output carries: tool, version, input, resolved input.
    nlohmann::json provenance(const std::string& inputFile,
                              const nlohmann::json& resolvedInput) const;

private:
    /// Prints one line per issue and returns the bad-input exit code.
    int reportInputError(const InputError& error) const;

    std::string m_name;
    std::string m_summary;
    bool m_quiet = false;
    bool m_printSchema = false;
    bool m_checkFailed = false;
    bool m_internalError = false;
    FiniteFlags m_finiteFlags;
};

/// The version line printed by --version and recorded in outputs.
std::string versionString();

} // namespace hvi::tool
