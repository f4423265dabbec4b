#include "tool/Tool.hpp"

#include "core/BuildInfo.hpp"
#include "io/Hdf5.hpp"
#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"

#include <exception>
#include <iostream>

namespace hvi::tool {

std::string versionString() {
    return std::string(build::kVersion) + " (" + build::kGitDescribe + ")";
}

Tool::Tool(std::string name, std::string summary)
    : m_name(std::move(name)), m_summary(std::move(summary)) {}

void Tool::warn(const std::string& message) const {
    std::cerr << m_name << ": warning: " << message << "\n";
}

void Tool::info(const std::string& message) const {
    if (!m_quiet) {
        std::cerr << m_name << ": " << message << "\n";
    }
}

nlohmann::json Tool::provenance(const std::string& inputFile,
                                const nlohmann::json& resolvedInput) const {
    return {{"tool", m_name},
            {"version", build::kVersion},
            {"git", build::kGitDescribe},
            {"input_file", inputFile},
            {"resolved_input", resolvedInput}};
}

int Tool::reportInputError(const InputError& error) const {
    for (const auto& issue : error.issues()) {
        std::cerr << m_name << ": " << issue.format() << "\n";
    }
    return static_cast<int>(ExitCode::BadInput);
}

int Tool::run(int argc, char** argv) {
    m_internalError = false;
    io::h5::skipCleanupAtExit(); // a failed write must not turn exit 3 into a crash at exit
    CLI::App app{m_summary, m_name};
    app.set_version_flag("--version", m_name + " " + versionString());
    app.add_flag("-q,--quiet", m_quiet, "Print only warnings and errors on stderr");
    if (!inputSchemaName().empty()) {
        app.add_flag("--print-schema", m_printSchema,
                     "Print the JSON Schema of the input file (with units) and exit");
    }
    app.footer("Exit codes: 0 ok, 1 check failed, 2 bad input or usage, 3 computation "
               "failed, 4 interrupted.");
    try {
        addOptions(app);
        m_finiteFlags.watch(app);
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e); // --help, --version
    } catch (const CLI::ParseError& e) {
        // A NaN or infinity is the likelier cause of a failed range check; name it first.
        if (!m_finiteFlags.issues().empty()) {
            return reportInputError(InputError(m_finiteFlags.issues()));
        }
        std::cerr << m_name << ": usage: " << e.what() << " (run '" << m_name
                  << " --help' for the options)\n";
        return static_cast<int>(ExitCode::BadInput);
    }
    if (!m_finiteFlags.issues().empty()) {
        return reportInputError(InputError(m_finiteFlags.issues()));
    }
    try {
        if (m_printSchema) {
            std::cout << io::jsonText(io::schema(inputSchemaName()), 2) << "\n";
            return static_cast<int>(ExitCode::Ok);
        }
        execute();
        return static_cast<int>(m_checkFailed ? ExitCode::CheckFailed : ExitCode::Ok);
    } catch (const InputError& e) {
        return reportInputError(e);
    } catch (const Interrupted& e) {
        std::cerr << m_name << ": " << e.what() << "\n";
        return static_cast<int>(ExitCode::Interrupted);
    } catch (const RuntimeFailure& e) {
        std::cerr << m_name << ": error: " << e.what() << "\n";
        return static_cast<int>(ExitCode::RuntimeFailure);
    } catch (const std::exception& e) {
        m_internalError = true;
        std::cerr << m_name << ": internal error: " << e.what() << "\n";
        return static_cast<int>(ExitCode::RuntimeFailure);
    }
}

} // namespace hvi::tool
