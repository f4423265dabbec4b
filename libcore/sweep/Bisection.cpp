#include "sweep/Bisection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hvi::sweep {

namespace {

/// True when a is the more severe value (the one more likely to perforate).
bool moreSevere(Direction d, double a, double b) {
    return d == Direction::FailsAsItGrows ? a > b : a < b;
}

/// One outward step from x: toward more severe values when `harsher`, else toward milder ones.
double stepFrom(const SearchSettings& s, double x, bool harsher) {
    const bool up = harsher == (s.direction == Direction::FailsAsItGrows);
    return up ? x * s.stepFactor : x / s.stepFactor;
}

void checkSettings(const SearchSettings& s) {
    if (!(s.guess > 0.0) || !(s.stepFactor > 1.0) || !(s.tolerance > 0.0) || s.maxPoints < 2 ||
        !(s.lowest > 0.0) || !(s.highest > s.lowest) || s.guess < s.lowest || s.guess > s.highest) {
        throw std::invalid_argument("search settings out of range: need 0 < lowest <= guess <= "
                                    "highest, step factor > 1, tolerance > 0, max points >= 2");
    }
}

} // namespace

SearchStep nextStep(const SearchSettings& s, const std::vector<SearchPoint>& points) {
    checkSettings(s);
    SearchStep step;
    // The P end: the mildest perforated value.
    for (const auto& p : points) {
        if (p.perforated && (!step.failSide || moreSevere(s.direction, *step.failSide, p.value))) {
            step.failSide = p.value;
        }
    }
    // The NP end: the harshest held value milder than the P end; held values beyond it are
    // out of order.
    for (const auto& p : points) {
        if (p.perforated) {
            continue;
        }
        if (step.failSide && !moreSevere(s.direction, *step.failSide, p.value)) {
            step.outOfOrder.push_back(p.value);
        } else if (!step.holdSide || moreSevere(s.direction, p.value, *step.holdSide)) {
            step.holdSide = p.value;
        }
    }
    std::sort(step.outOfOrder.begin(), step.outOfOrder.end());

    if (step.failSide && step.holdSide) {
        if (std::abs(*step.failSide - *step.holdSide) <= s.tolerance) {
            step.state = SearchState::Converged;
            return step;
        }
        step.next = 0.5 * (*step.failSide + *step.holdSide);
    } else if (step.failSide || step.holdSide) {
        // One verdict so far: step beyond the mildest P (toward NP) or the harshest NP.
        const double from = step.failSide ? *step.failSide : *step.holdSide;
        const double wanted = std::clamp(stepFrom(s, from, !step.failSide), s.lowest, s.highest);
        if (wanted == from) {
            step.state = SearchState::Unbracketed;
            return step;
        }
        step.next = wanted;
    } else {
        step.next = s.guess;
    }
    if (static_cast<int>(points.size()) >= s.maxPoints) {
        step.state = SearchState::PointLimit;
    }
    return step;
}

const char* toString(SearchState state) {
    switch (state) {
    case SearchState::RunNext:
        return "run-next";
    case SearchState::Converged:
        return "converged";
    case SearchState::Unbracketed:
        return "unbracketed";
    case SearchState::PointLimit:
        return "point-limit";
    }
    return "?";
}

} // namespace hvi::sweep
