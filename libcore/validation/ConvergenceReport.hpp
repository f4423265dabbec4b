// The error-against-run-time study of one case over a ladder of particle spacings (issue #22,
// item 2; the source study did it by hand in its particle-size study, Sec. 3.3.1): `make
// convergence` runs the case at each spacing into OUT/s<spacing>/ (run-rules.mk) and this
// gathers the verdicts into a CSV, a markdown table and a log-log plot.
//
// Per spacing: SPH particles and FE elements at the start, steps, wall time, the bumper hole,
// the penetration depth, the verdict and the energy error (verdict.json). Per metric, the
// observed order and the Richardson estimate at zero spacing from the three finest spacings
// (validation/Richardson.hpp), and each spacing's error against it; the bumper hole also
// against its measurement when the case has one.
#pragma once

#include "plot/XyPlot.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hvi::validation {

struct LadderRun {
    double spacingMm = 0.0;
    std::string verdict, grade;
    std::optional<double> holeMm, depthMm, energyError, wallS;
    std::optional<double> particles, elements, steps;
};

/// The runs of OUT/s<spacing>/verdict.json, coarsest first; directories without a verdict
/// are left out. Throws InputError for a verdict without the fields above.
std::vector<LadderRun> readLadder(const std::filesystem::path& outDir);

struct ConvergenceOptions {
    std::string id;                       ///< the case
    std::string setup;                    ///< one line: end time, domain, threads
    std::optional<double> measuredHoleMm; ///< the test's bumper hole, when measured
    /// The source study's own particle-size study of this case (thesis_cases.json
    /// calibration.particle_size_study), when it has one; null otherwise.
    std::string sourceStudyMarkdown;
    /// Its runs as (wall time [s], hole error [%]) for the plot, where both are reported.
    std::vector<std::pair<double, double>> sourceStudyPoints;
    std::string plotLink; ///< the plot's path as the markdown links it (empty: no plot)
};

std::string convergenceCsv(const std::vector<LadderRun>& runs);
std::string convergenceMarkdown(const std::vector<LadderRun>& runs,
                                const ConvergenceOptions& options);
/// Error [%] against wall time [s], log-log: the hole against its measurement and against
/// its Richardson estimate, the depth against its estimate, the energy error.
plot::XyPlot convergencePlot(const std::vector<LadderRun>& runs, const ConvergenceOptions& options);

/// The source study's particle-size study of `caseId` as a markdown table (empty when the
/// study was of another case).
std::string sourceStudyTable(const std::string& caseId);

/// The source study's runs of `caseId` as (wall time [s], hole error [%]) where it reports
/// both (empty for another case).
std::vector<std::pair<double, double>> sourceStudyPoints(const std::string& caseId);

/// The measured bumper hole of a source-study case (thesis_cases.json expected
/// bumper_hole_diameter_mm), when it has one.
std::optional<double> measuredBumperHoleMm(const std::string& caseId);

} // namespace hvi::validation
