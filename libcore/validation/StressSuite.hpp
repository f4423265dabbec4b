// The stiff and extreme suite (issue #25): scenes at the edges of what the solver is asked to
// do (impacts from 0.5 to 30 km/s, steel and tungsten on thin aluminium, layers one and two
// points thick, a 10:1 spread of element sizes, a one-point projectile on the axis, a
// projectile that strikes nothing), run by `make -C workflows extreme` into OUT/<name>/run.h5
// and tabulated here: for each, how the run ended, whether every field of its last snapshot
// is finite, its largest energy error, its smallest time step with when and what set it, and
// its wall time. The point is that each ends cleanly, not that it is accurate.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hvi::validation {

struct StressRun {
    std::string name, description;
    std::string status, stopReason; ///< /run@status ("complete", "partial") and its reason;
                                    ///< "failed" and hvi-run's exit and last line
    std::string nonFinite;          ///< the first field of the last snapshot with a NaN or
                                    ///< infinity ("" when all are finite)
    std::optional<double> energyError, minDtUs, minDtTimeUs, wallS, endUs;
    std::string minDtLimiter;
    long steps = 0;
};

/// The runs of OUT/<name>/run.h5, by name, and the runs that failed (OUT/<name>/failed, as
/// make extreme records them); a directory with neither is left out.
std::vector<StressRun> readStressRuns(const std::filesystem::path& outDir);

/// The first non-finite value of `run`'s last snapshot, as "particles/Pressure" or
/// "elements/Density"; empty when every value is finite.
std::string firstNonFiniteField(const std::filesystem::path& runFile);

std::string stressReport(const std::vector<StressRun>& runs);

} // namespace hvi::validation
