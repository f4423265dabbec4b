// The evolving set: every particle that has been evaluated, pushed by contact or created
// since the start of the run (it only grows). The others have never moved: they sit in their
// reference state with zero rates, where a kick or a drift changes nothing, so the time loop
// skips them exactly. Kept sorted without repeats, so a body's slice is a binary search away
// and the loops visit memory in order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hvi::solver {

class EvolvingSet {
public:
    /// No particle of `n` evolves (the start of a run).
    void clear(std::size_t n);
    /// Every particle of `n` evolves (a resume: which ones did is not checkpointed).
    void fill(std::size_t n);
    /// Adds the particles not yet in the set.
    void include(std::span<const int32_t> items);

    const std::vector<int32_t>& items() const { return m_items; }
    std::size_t size() const { return m_items.size(); }
    bool contains(std::size_t i) const { return m_flag[i] != 0; }

private:
    std::vector<int32_t> m_items; ///< sorted, unique
    std::vector<uint8_t> m_flag;  ///< per particle
};

} // namespace hvi::solver
