// Where a run's wall time goes, so a slow case says why it is slow: each package's time by
// phase of the step (Package.hpp) and by named section inside a phase (the SPH neighbour
// search, the conversion of eroded elements), the time loop's own work (deleting points, the
// stop rules, writing snapshots and checkpoints), and the time steps taken with what set them.
// hvi-run prints it at the end of a run and keeps it in the run file (/run@profile).
//
// Step sizes go into a histogram of 1 %-wide logarithmic bins instead of a list, so a run of
// millions of steps keeps a few kilobytes; a percentile is good to the bin width.
//
// Units: wall time in s, steps in us.
#pragma once

#include "solver/BinnedWork.hpp"

#include <array>
#include <chrono>
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace hvi::solver {

/// The phases of a step (Package.hpp), and the preparation before the first one.
enum class Phase { Kick, Constrain, Drift, Evaluate, KickAgain, Finish, Prepare };
inline constexpr std::size_t kPhaseCount = 7;
inline constexpr std::array<std::string_view, kPhaseCount> kPhaseNames{
    "kick", "constrain", "drift", "evaluate", "kick_again", "finish", "prepare"};

/// One package's wall time [s], by phase and by section (a named part of a phase).
class PhaseTimes {
public:
    void book(Phase phase, double seconds) { m_phase[static_cast<std::size_t>(phase)] += seconds; }
    /// Time of a named part of some phase (already counted in that phase's time).
    void bookSection(std::string_view name, double seconds);

    double phase(Phase phase) const { return m_phase[static_cast<std::size_t>(phase)]; }
    double total() const;
    const std::vector<std::pair<std::string, double>>& sections() const { return m_sections; }

private:
    std::array<double, kPhaseCount> m_phase{};
    std::vector<std::pair<std::string, double>> m_sections; // in the order first booked
};

/// The sizes of the steps a run took and which package's vote set each.
class StepSizeHistogram {
public:
    void add(double dtUs, const std::string& limiter);

    long count() const { return m_count; }
    double min() const { return m_min; }
    double max() const { return m_max; }
    /// The step below which a fraction q of the steps lie [us], to the 1 % bin width;
    /// 0 with no steps.
    double percentile(double q) const;
    /// Steps set by each package.
    const std::map<std::string, long>& limiterSteps() const { return m_limiters; }

private:
    std::map<int, long> m_bins; // bin k holds steps in [base^k, base^(k+1)) us
    std::map<std::string, long> m_limiters;
    long m_count = 0;
    double m_min = 0.0;
    double m_max = 0.0;
};

/// The wall time since construction [s].
class Stopwatch {
public:
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    }

private:
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

/// A run's profile: packages in their loop order, the loop's own work, the steps.
struct RunProfile {
    std::vector<std::pair<std::string, PhaseTimes>> packages;
    std::vector<std::pair<std::string, double>> loop; ///< deletion, stop rules, output [s]
    StepSizeHistogram steps;
    /// What time-step bins would have evaluated, per package with points of its own.
    std::vector<std::pair<std::string, BinnedWork>> binned;
    double wallSeconds = 0.0; ///< the whole run, for the share of each part
};

/// The profile as the run file keeps it.
nlohmann::json profileJson(const RunProfile& profile);

/// The profile as hvi-run prints it at the end of a run: a few lines, no trailing newline.
std::string profileText(const RunProfile& profile);

} // namespace hvi::solver
