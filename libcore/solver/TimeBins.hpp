// Time-step bins for the SPH particles: each particle steps over an interval of 2^k steps of
// the scene (the base step, the smallest vote times the Courant factor), k chosen from its
// own stable step, so that the cold material beside an impact is evaluated a fraction as often
// as the hot particles that set the base step. After the individual time steps of tree and SPH
// codes (Springel, MNRAS 364 (2005) 1105, sec. 4: kick-drift-kick per particle on a
// power-of-two hierarchy; SWIFT, Schaller et al., MNRAS 530 (2024) 2378, sec. 4) with the
// wake-up of Saitoh & Makino, ApJ 697 (2009) L99: no particle steps more than 4 times longer
// than an evaluated neighbour.
//
// One interval [t0, t0 + T] of particle i, in the leapfrog of solver/HalfStep.hpp:
//   opening kick (its first base step):  half := state(t0) + (T_plan / 2) rate(t0)
//   every base step: positions drift with the half-step velocity; the state the neighbours
//     read is the prediction state(t) = half + (t - t0 - T_plan / 2) rate(t0)
//   closing (the base step that ends the interval, T = the time actually elapsed):
//     half += ((T - T_plan) / 2) rate(t0) when T differs from the plan (the base step changed,
//     or the particle was woken), state := half + (T / 2) rate(t0 + T), after an evaluation
//     at the predicted state.
// With every particle in the first bin (T = T_plan = the base step) this is the global
// leapfrog, bit for bit. An interval closes after its 2^k base steps, when a neighbour's
// evaluation wakes it, or when a next base step as long as the current one would carry it
// past its own stable step (times the Courant factor). Particles that have not been evaluated yet (a new particle, a
// dormant one that wakes) start in the first bin. The pair forces of two particles in
// different bins are evaluated at different times, so momentum is conserved to the order of
// the scheme, not to round-off (as in the codes above); contact is evaluated every base step.
//
// Units: us.
#pragma once

#include "io/Checkpoint.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hvi::solver {

class TimeBins {
public:
    /// The longest interval, 2^kMaxLevel base steps.
    static constexpr int kMaxLevel = 6;
    /// A particle steps at most 2^kWakeLevels times longer than an evaluated neighbour.
    static constexpr int kWakeLevels = 2;

    /// Every point of `n` opens an interval of one base step at its next step.
    void reset(std::size_t n);

    /// The start of a base step of length dt [us]: the evolving alive points between
    /// intervals open one (its length from their vote, `cfl` times their stable step), and
    /// each marks whether this step closes its interval. Fills opening() and closing().
    void beginStep(std::span<const int32_t> evolving, const std::vector<uint8_t>& alive,
                   double cfl, double dt);
    /// The points that open an interval this step, and those whose interval this step closes
    /// (both ascending; the evolving points of the step only).
    const std::vector<int32_t>& opening() const { return m_opening; }
    const std::vector<int32_t>& closing() const { return m_closing; }
    /// The closing points whose interval ends otherwise than planned (the base step changed,
    /// or they were woken): their half step is corrected first.
    const std::vector<int32_t>& shortened() const { return m_shortened; }
    /// Whether point i's rates are evaluated at the end of this step: its interval closes, or
    /// it did not evolve before (a new or newly woken particle, one base step).
    bool evaluated(std::size_t i) const { return m_due[i] != 0; }

    /// Half the planned interval (the opening kick), the prediction offset of this step's end
    /// (the drift), the half-step correction and half the actual interval (the closing kick).
    double openingHalf(std::size_t i) const { return 0.5 * m_planned[i]; }
    double predictionOffset(std::size_t i) const { return m_offset[i]; }
    double closingCorrection(std::size_t i) const { return 0.5 * (m_interval[i] - m_planned[i]); }
    double closingHalf(std::size_t i) const { return 0.5 * m_interval[i]; }
    /// The interval the closing step ends, the step of the plasticity and damage update [us].
    double interval(std::size_t i) const { return m_interval[i]; }
    const std::vector<double>& intervals() const { return m_interval; }

    /// Whether point i was among the evolving alive points of this step's beginStep(); one
    /// that joined them since (a particle set moving by contact, or made from an eroded
    /// element) has no interval yet, and opens one at the next step.
    bool begun(std::size_t i) const { return m_stepStamp[i] == m_stepCount; }
    /// A point evaluated for the first time in this base step of length dt [us] (it did not
    /// evolve when the step began): one base step, starting now.
    void admit(std::size_t i, double dt);
    /// Point i's own stable step from its evaluation [us] (+inf: it sets none).
    void setVote(std::size_t i, double stableStep) { m_vote[i] = stableStep; }
    double vote(std::size_t i) const { return m_vote[i]; }
    /// The bin an evaluated point of vote `stableStep` would take at base step dt [us].
    static int levelFor(double cfl, double stableStep, double dt, int cap);
    /// An evaluated point of bin `level` next to point j: j's next interval is at most
    /// kWakeLevels longer, and a longer one running now closes at the end of the next step.
    /// Thread-safe (relaxed atomics; the outcome does not depend on the order).
    void wakeNeighbour(std::size_t j, int level) { limit(j, level + kWakeLevels); }
    /// Point j's next interval is in bin `bound` at most, and a longer one running now closes
    /// at the end of the next step (thread-safe as wakeNeighbour).
    void limit(std::size_t j, int32_t bound) {
        std::atomic_ref<int32_t> cap(m_cap[j]);
        int32_t seen = cap.load(std::memory_order_relaxed);
        while (seen > bound &&
               !cap.compare_exchange_weak(seen, bound, std::memory_order_relaxed)) {
        }
        // Only an interval in its course: one closing now reopens under the cap anyway.
        if (m_level[j] > bound && m_due[j] == 0) {
            std::atomic_ref<int32_t>(m_woken[j]).store(1, std::memory_order_relaxed);
        }
    }

    /// The end of the base step dt [us]: closed intervals end, the others that began the step
    /// advance.
    void endStep(std::span<const int32_t> evolving, const std::vector<uint8_t>& alive, double dt);

    /// Its arrays into a checkpoint under `prefix`, and back.
    void save(io::CheckpointState& state, const std::string& prefix) const;
    void restore(const io::CheckpointState& state, const std::string& prefix);

private:
    std::vector<int32_t> m_level;  ///< bin of the current interval (2^level base steps)
    std::vector<int32_t> m_taken;  ///< base steps of the current interval taken
    std::vector<int32_t> m_cap;    ///< the longest bin its next interval may take
    std::vector<int32_t> m_woken;  ///< 1: a neighbour asks the interval to close
    std::vector<double> m_elapsed; ///< time of the interval before this step [us]
    std::vector<double> m_planned; ///< the interval's planned length [us]
    std::vector<double> m_vote;    ///< its stable step at its last evaluation [us] (0: none yet)
    std::vector<double> m_interval; ///< elapsed time at the end of this step [us]
    std::vector<double> m_offset;   ///< this step's prediction offset [us]
    std::vector<uint8_t> m_due;    ///< this step closes its interval
    std::vector<int64_t> m_stepStamp; ///< the count of the last beginStep() it was in
    int64_t m_stepCount = 0;          ///< beginStep() calls (not checkpointed: per step)
    std::vector<int32_t> m_opening, m_closing, m_shortened;
};

} // namespace hvi::solver
