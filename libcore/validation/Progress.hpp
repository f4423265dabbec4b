// The progress line of a long validation (issue #22, item 5): after each finished case, how
// many are done, how many are left, and when the rest should be done, from the wall times of
// the runs so far. A case is done when its verdict.json exists (OUT/<id>/verdict.json, as
// `make validate` writes it); its run time is the verdict's wall_time_s.
#pragma once

#include "validation/ValidationCase.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace hvi::validation {

struct Progress {
    std::size_t total = 0;
    std::size_t done = 0;
    std::size_t timed = 0;  ///< done cases with a run time
    double meanWallS = 0.0; ///< their mean run time [s]
};

Progress progressOf(const std::vector<Case>& cases, const std::filesystem::path& outDir);

/// "validate: 14/116 cases done, 102 left, about 8 h 30 min to go at 2 jobs (mean 600 s a
/// run)"; "all 116 cases done" at the end; no estimate before a run is timed.
std::string progressLine(const Progress& progress, int jobs);

} // namespace hvi::validation
