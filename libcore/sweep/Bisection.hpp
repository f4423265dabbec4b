// The bracketing search behind a simulated ballistic limit: which value of one shield or threat
// parameter (projectile diameter, rear-wall thickness) to run next, from the verdicts of the
// runs done so far, until a perforated (P) and a held (NP) run lie within a tolerance.
//
// It starts at a guess (the ballistic limit equation's value), steps outward by a constant
// factor until the verdict flips, then halves the bracket. The decision depends only on the
// points already run, never on their order, so an interrupted sweep resumes from its run
// directories alone. Units: whatever the parameter's are (mm here); the tolerance is absolute.
//
// The verdict need not be monotone in the parameter near the limit (a simulated shield, like a
// tested one, can hold at a larger diameter than one it failed at). The bracket is then the
// one around the P-side limit: the smallest P value (for a parameter that makes failure more
// likely as it grows) and the largest NP value below it; the NP values beyond it are reported.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hvi::sweep {

/// How the verdict moves with the parameter.
enum class Direction {
    FailsAsItGrows, ///< e.g. projectile diameter
    HoldsAsItGrows, ///< e.g. rear-wall thickness
};

struct SearchSettings {
    Direction direction = Direction::FailsAsItGrows;
    double guess = 0.0;       ///< first value to run, > 0
    double stepFactor = 1.25; ///< outward step while unbracketed, > 1
    double tolerance = 0.0;   ///< bracket width at which the search stops, > 0
    int maxPoints = 12;       ///< runs after which the search stops unresolved
    double lowest = 0.0;      ///< the search never proposes a value below this (> 0)
    double highest = 0.0;     ///< ... or above this
};

struct SearchPoint {
    double value = 0.0;
    bool perforated = false;
};

enum class SearchState {
    RunNext,     ///< `next` holds the value to run
    Converged,   ///< a P and an NP within the tolerance
    Unbracketed, ///< every run gave the same verdict up to the allowed range
    PointLimit,  ///< maxPoints runs without converging
};

struct SearchStep {
    SearchState state = SearchState::RunNext;
    double next = 0.0;              ///< RunNext: the value to run
    std::optional<double> failSide; ///< the P end of the bracket
    std::optional<double> holdSide; ///< the NP end of the bracket
    std::vector<double> outOfOrder; ///< NP values on the P side of failSide
};

/// The next step of the search. Throws std::invalid_argument for settings out of range.
SearchStep nextStep(const SearchSettings& settings, const std::vector<SearchPoint>& points);

/// "run-next", "converged", "unbracketed", "point-limit".
const char* toString(SearchState state);

} // namespace hvi::sweep
