// docs/validation.md from the outputs of `make -C workflows validate`: for every case the
// test's result, ours with its damage grade, whether it rests on the axis band alone, the
// ballistic limit equation's d/d_c and verdict for the same shield, run time and energy
// error; then accuracy per shield type and per speed range beside the equation's on the same
// cases, the confusion matrix, and the wall time of the set; where verdicts of the same
// cases are kept at other spacings, the verdicts side by side (verdict stability); and where
// they are kept with a material library laid over the built-in one (a sensitivity study, e.g.
// the spall strength at the ends of its range), those side by side with how many move and
// each variant's agreement with the tests on the cases it ran.
//
// A case directory OUT/<id>/ holds verdict.json (hvi-assess) and ble.json (ble-size); a
// case without a verdict is listed as not run and left out of the accuracy of the model, not
// of the equation's.
#pragma once

#include "validation/ValidationCase.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hvi::validation {

struct ReportOptions {
    std::string selection = "all";
    std::string resolution; ///< as given to the workflow, for the header ("" = unknown)
    /// Kept verdicts of the same cases at other spacings (label, directory of <id>.json), for
    /// the verdict-stability table; cases with none there are left out of it.
    std::vector<std::pair<std::string, std::filesystem::path>> otherSpacings;
    /// Kept verdicts of the same cases at this spacing with another material library (label,
    /// directory of <id>.json), for the sensitivity table; cases with none are left out.
    std::vector<std::pair<std::string, std::filesystem::path>> variants;
};

/// The markdown text. Throws InputError naming the file for an unreadable verdict or sizing.
std::string validationReport(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                             const ReportOptions& options);

} // namespace hvi::validation
