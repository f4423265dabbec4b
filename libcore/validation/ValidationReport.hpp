// docs/validation.md from the outputs of `make -C workflows validate`: for every case the
// test's result, ours with its damage grade, whether it rests on the axis band alone, the
// ballistic limit equation's d/d_c and verdict for the same shield, run time and energy
// error; then accuracy per shield type and per speed range beside the equation's on the same
// cases, the confusion matrix, and the wall time of the set; and, where verdicts of the same
// cases are kept at other spacings, the verdicts side by side (verdict stability).
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
};

/// The markdown text. Throws InputError naming the file for an unreadable verdict or sizing.
std::string validationReport(const std::vector<Case>& cases, const std::filesystem::path& outDir,
                             const ReportOptions& options);

} // namespace hvi::validation
