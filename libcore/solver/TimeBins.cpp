#include "solver/TimeBins.hpp"

#include "core/Parallel.hpp"
#include "io/CheckpointFields.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::solver {

void TimeBins::reset(std::size_t n) {
    m_level.assign(n, 0);
    m_taken.assign(n, 0);
    m_cap.assign(n, kMaxLevel);
    m_woken.assign(n, 0);
    m_elapsed.assign(n, 0.0);
    m_planned.assign(n, 0.0);
    m_vote.assign(n, 0.0);
    m_interval.assign(n, 0.0);
    m_offset.assign(n, 0.0);
    m_due.assign(n, 1);
    m_stepStamp.assign(n, -1);
    m_stepCount = 0;
    m_opening.clear();
    m_closing.clear();
    m_shortened.clear();
}

int TimeBins::levelFor(double cfl, double stableStep, double dt, int cap) {
    const double limit = cfl * stableStep;
    int level = 0;
    while (level < cap && std::ldexp(dt, level + 1) <= limit) {
        ++level;
    }
    return level;
}

void TimeBins::beginStep(std::span<const int32_t> evolving, const std::vector<uint8_t>& alive,
                         double cfl, double dt) {
    const std::size_t count = evolving.size();
    ++m_stepCount;
    parallelFor(count, [&](std::size_t a) {
        const auto i = static_cast<std::size_t>(evolving[a]);
        if (!alive[i]) {
            m_due[i] = 0;
            return;
        }
        m_stepStamp[i] = m_stepCount;
        if (m_taken[i] == 0) {
            m_level[i] = levelFor(cfl, m_vote[i], dt, std::min(m_cap[i], kMaxLevel));
            m_planned[i] = std::ldexp(dt, m_level[i]);
            m_elapsed[i] = 0.0;
            m_cap[i] = kMaxLevel;
        }
        m_interval[i] = m_elapsed[i] + dt;
        const bool last = m_taken[i] + 1 >= (1 << m_level[i]);
        // Close now if a next base step as long as this one would carry the interval past
        // the point's own stable step. The base step grows by at most kMaxDtGrowth a step, so
        // an interval ends at most a quarter of a base step past it: past cfl times the stable
        // step by at most an eighth, in the second bin, and less in the longer ones.
        const bool overrun = m_interval[i] + dt > cfl * m_vote[i];
        m_due[i] = (last || m_woken[i] != 0 || overrun) ? 1 : 0;
        m_woken[i] = 0;
        m_offset[i] = m_due[i] != 0 ? 0.5 * m_interval[i] : m_interval[i] - 0.5 * m_planned[i];
    });
    m_opening.clear();
    m_closing.clear();
    m_shortened.clear();
    for (const int32_t i : evolving) {
        const auto k = static_cast<std::size_t>(i);
        if (!alive[k]) {
            continue;
        }
        if (m_taken[k] == 0) {
            m_opening.push_back(i);
        }
        if (m_due[k] != 0) {
            m_closing.push_back(i);
            if (m_interval[k] != m_planned[k]) {
                m_shortened.push_back(i);
            }
        }
    }
}

void TimeBins::admit(std::size_t i, double dt) {
    m_level[i] = 0;
    m_taken[i] = 0;
    m_elapsed[i] = 0.0;
    m_planned[i] = dt;
    m_interval[i] = dt;
    m_due[i] = 1;
}

void TimeBins::endStep(std::span<const int32_t> evolving, const std::vector<uint8_t>& alive,
                       double dt) {
    parallelFor(evolving.size(), [&](std::size_t a) {
        const auto i = static_cast<std::size_t>(evolving[a]);
        if (!alive[i] || !begun(i)) {
            return; // an admitted point is due, so its interval ends here too (taken 0)
        }
        if (m_due[i] != 0) {
            m_taken[i] = 0;
        } else {
            ++m_taken[i];
            m_elapsed[i] += dt;
        }
    });
}

void TimeBins::save(io::CheckpointState& s, const std::string& prefix) const {
    s.ints[prefix + "level"] = m_level;
    s.ints[prefix + "taken"] = m_taken;
    s.ints[prefix + "cap"] = m_cap;
    s.ints[prefix + "woken"] = m_woken;
    s.doubles[prefix + "elapsed_us"] = m_elapsed;
    s.doubles[prefix + "planned_us"] = m_planned;
    s.doubles[prefix + "vote_us"] = m_vote;
}

void TimeBins::restore(const io::CheckpointState& s, const std::string& prefix) {
    io::takeArray(s, prefix + "level", m_level);
    io::takeArray(s, prefix + "taken", m_taken);
    io::takeArray(s, prefix + "cap", m_cap);
    io::takeArray(s, prefix + "woken", m_woken);
    io::takeArray(s, prefix + "elapsed_us", m_elapsed);
    io::takeArray(s, prefix + "planned_us", m_planned);
    io::takeArray(s, prefix + "vote_us", m_vote);
}

} // namespace hvi::solver
