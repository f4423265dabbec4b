// What time-step bins would evaluate (issue #27): on a power-of-two hierarchy of steps, as in
// SWIFT and Gadget (Springel, MNRAS 364 (2005) 1105, section 5), each point steps at the
// largest step 2^k dt_min not above its own stable step, so over 2^k of the smallest steps it
// is evaluated once where the single-step loop evaluates it 2^k times. Counting, at every
// step the loop takes, the points it evaluates and the share 2^-k each would cost in its
// bin gives the work bins would leave: the bound on what they can save before the wake-ups
// of the time-step limiter (Saitoh and Makino, ApJ 697 (2009) L99) and the bookkeeping.
//
// Units: us for steps (only their ratios enter).
#pragma once

#include <cstddef>
#include <span>

namespace hvi::solver {

class BinnedWork {
public:
    /// Bins up to 2^kMaxBin times the smallest step: a point there costs 1/64 of an
    /// evaluation, so higher bins would save under 2 % of one.
    static constexpr int kMaxBin = 6;

    /// One step's evaluated points, each with its own stable step [us] (+inf: it sets no
    /// limit, the top bin), against the smallest vote of the step [us] (> 0).
    void add(std::span<const double> pointSteps, double smallestStep);

    /// Point-evaluations the single-step loop made, and what bins would have made.
    double evaluated() const { return m_evaluated; }
    double binned() const { return m_binned; }
    /// binned / evaluated (1 with nothing evaluated).
    double fraction() const { return m_evaluated > 0.0 ? m_binned / m_evaluated : 1.0; }

    /// The bin of a point whose stable step is `ratio` times the smallest (>= 0, clamped).
    static int binOf(double ratio);

private:
    /// 2^b: the smallest ratio of bin b.
    static constexpr double kBinEdge[kMaxBin + 1] = {1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0};
    double m_evaluated = 0.0;
    double m_binned = 0.0;
};

} // namespace hvi::solver
