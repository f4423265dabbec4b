#include "app/HviValidateTool.hpp"

#include "io/AtomicOutput.hpp"
#include "io/JsonText.hpp"
#include "plot/XyPlot.hpp"
#include "validation/CaseInputs.hpp"
#include "validation/ConvergenceReport.hpp"
#include "validation/Progress.hpp"
#include "validation/StressSuite.hpp"
#include "validation/ValidationReport.hpp"

#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace hvi::app {

namespace fs = std::filesystem;

namespace {

/// A directory of kept verdicts given by a flag (`pointer`), without a trailing slash; an
/// InputError naming the flag when it is none.
fs::path keptDirectory(const std::string& dir, const char* pointer, const char* example) {
    if (!fs::is_directory(dir)) {
        throw InputError("<flags>", pointer, dir + " is no directory",
                         std::string("a directory of kept verdicts, e.g. ") + example);
    }
    fs::path path(dir);
    return path.filename().empty() ? path.parent_path() : path; // a trailing slash
}

} // namespace

HviValidateTool::HviValidateTool()
    : tool::Tool("hvi-validate", "Validation cases (the source study's and the NASA development "
                                 "set): list them, write each one's tool inputs, and report "
                                 "the verdicts against the tests") {}

void HviValidateTool::addOptions(CLI::App& app) {
    app.add_option("action", m_action, "list | inputs | report | progress | convergence | extreme")
        ->required()
        ->check(CLI::IsMember({"list", "inputs", "report", "progress", "convergence", "extreme"}));
    app.add_option("case", m_case, "Case id (inputs)");
    app.add_option("--set", m_set,
                   "Cases: all (default), source_study, development, or quick (the bracketing "
                   "pairs A1076/A1077 and HITF03147-2/-3)");
    app.add_option("--out-dir", m_outDir, "inputs: where to write; report: the case directories");
    app.add_option("-o,--output", m_output, "report: the markdown file ('-' = stdout)");
    app.add_option("--resolution-mm", m_resolution, "report: the spacing the runs used [mm]");
    app.add_option("--compare-kept", m_compareKept,
                   "report: a directory of kept verdicts (<case>.json) at another spacing, named "
                   "by that spacing (data/validation/verdicts/0.04); repeatable: the "
                   "verdict-stability table");
    app.add_option("--sensitivity-kept", m_sensitivityKept,
                   "report: a directory of kept verdicts (<case>.json) at this spacing with "
                   "another material library, named by the directory above it "
                   "(data/validation/sensitivity/spall-0.8/0.08); repeatable: the sensitivity "
                   "table");
    app.add_flag("--interleave", m_interleave,
                 "list: the shield types in turn (the run order of make validate)");
    app.add_option("--csv", m_csv, "convergence: also the table as CSV");
    app.add_option("--plot", m_plot, "convergence: error against wall time, log-log (.svg/.png)");
    app.add_option("--measured-hole-mm", m_measuredHoleMm,
                   "convergence: the test's bumper hole [mm] (default: the case's, if measured)")
        ->check(CLI::PositiveNumber);
    app.add_option("--setup", m_setup, "convergence: one line on how the ladder was run");
    app.add_option("--jobs", m_jobs, "progress: runs side by side, for the estimate (default 1)")
        ->check(CLI::PositiveNumber);
}

void HviValidateTool::convergence() const {
    if (m_outDir.empty()) {
        throw InputError("<flags>", "/out_dir", "convergence needs --out-dir",
                         "the ladder's directory (s<spacing>/ in it)");
    }
    const auto runs = validation::readLadder(m_outDir);
    if (runs.empty()) {
        throw InputError(m_outDir, "", "holds no run of the ladder",
                         "s<spacing>/verdict.json files (make -C workflows convergence)");
    }
    validation::ConvergenceOptions options;
    options.id = m_case.empty() ? fs::path(m_outDir).filename().string() : m_case;
    options.setup = m_setup;
    options.sourceStudyMarkdown = validation::sourceStudyTable(m_case);
    options.sourceStudyPoints = validation::sourceStudyPoints(m_case);
    if (m_measuredHoleMm > 0.0) {
        options.measuredHoleMm = m_measuredHoleMm;
    } else if (const auto measured = validation::measuredBumperHoleMm(m_case)) {
        options.measuredHoleMm = measured;
    }
    if (!m_plot.empty()) {
        const fs::path mdDir =
            m_output == "-" ? fs::current_path() : fs::absolute(fs::path(m_output)).parent_path();
        options.plotLink = fs::absolute(m_plot).lexically_relative(mdDir).string();
        plot::writePlot(validation::convergencePlot(runs, options), m_plot);
    }
    if (!m_csv.empty()) {
        io::writeTextAtomically(m_csv, validation::convergenceCsv(runs));
    }
    const std::string text = validation::convergenceMarkdown(runs, options);
    if (m_output == "-") {
        std::cout << text;
        return;
    }
    io::writeTextAtomically(m_output, text);
    info(options.id + ": " + std::to_string(runs.size()) + " spacings -> " + m_output);
}

void HviValidateTool::execute() {
    if (m_action == "convergence") {
        convergence();
        return;
    }
    if (m_action == "extreme") { // the stiff and extreme suite's table
        if (m_outDir.empty()) {
            throw InputError("<flags>", "/out_dir", "extreme needs --out-dir",
                             "the suite's directory (<case>/run.h5 in it)");
        }
        const std::string text = validation::stressReport(validation::readStressRuns(m_outDir));
        if (m_output == "-") {
            std::cout << text;
        } else {
            io::writeTextAtomically(m_output, text);
        }
        return;
    }
    std::vector<validation::Case> cases;
    try {
        cases = validation::selectCases(m_set);
    } catch (const std::invalid_argument& e) {
        throw InputError("<flags>", "/set", e.what(),
                         "all, source_study, development, quick or ci");
    }
    if (m_action == "list") {
        for (const auto& c : m_interleave ? validation::interleavedByShield(cases) : cases) {
            std::cout << c.id << "\n";
        }
        return;
    }
    if (m_outDir.empty()) {
        throw InputError("<flags>", "/out_dir", "--out-dir is missing",
                         "the directory of the case files");
    }
    if (m_action == "inputs") {
        const validation::Case* c = nullptr;
        try {
            c = &validation::findCase(m_case);
        } catch (const std::invalid_argument& e) {
            throw InputError("<flags>", "/case", e.what(), "an id that 'hvi-validate list' prints");
        }
        const fs::path dir(m_outDir);
        fs::create_directories(dir);
        // panel.json last: it is the workflow's target, so it exists only with the others.
        io::writeTextAtomically(dir / "constraints.json",
                                io::jsonText(validation::bleConstraints(*c), 2) + "\n");
        io::writeTextAtomically(dir / "writer", validation::sceneWriterOf(*c) + "\n");
        io::writeTextAtomically(dir / "panel.json",
                                io::jsonText(validation::panelInput(*c), 2) + "\n");
        info(c->id + ": " + validation::toString(c->shield) + ", test " + c->result + " -> " +
             dir.string());
        return;
    }
    if (m_action == "progress") { // one line on stderr, after each finished case
        std::cerr << validation::progressLine(validation::progressOf(cases, m_outDir), m_jobs)
                  << "\n";
        return;
    }
    validation::ReportOptions options;
    options.selection = m_set;
    options.resolution = m_resolution;
    for (const auto& dir : m_compareKept) {
        const fs::path path = keptDirectory(dir, "/compare_kept", "data/validation/verdicts/0.04");
        options.otherSpacings.emplace_back(path.filename().string(), path);
    }
    for (const auto& dir : m_sensitivityKept) {
        const fs::path path =
            keptDirectory(dir, "/sensitivity_kept", "data/validation/sensitivity/spall-0.8/0.08");
        options.variants.emplace_back(path.parent_path().filename().string(), path);
    }
    const std::string text = validation::validationReport(cases, m_outDir, options);
    if (m_output == "-") {
        std::cout << text;
    } else {
        io::writeTextAtomically(m_output, text);
    }
}

} // namespace hvi::app
