#include "solver/EvolvingSet.hpp"

#include <algorithm>
#include <numeric>

namespace hvi::solver {

void EvolvingSet::clear(std::size_t n) {
    m_items.clear();
    m_flag.assign(n, 0);
}

void EvolvingSet::fill(std::size_t n) {
    m_items.resize(n);
    std::iota(m_items.begin(), m_items.end(), 0);
    m_flag.assign(n, 1);
}

void EvolvingSet::include(std::span<const int32_t> items) {
    const std::size_t before = m_items.size();
    for (const int32_t i : items) {
        auto& flag = m_flag[static_cast<std::size_t>(i)];
        if (!flag) {
            flag = 1;
            m_items.push_back(i);
        }
    }
    if (m_items.size() != before) {
        // The newcomers sorted among themselves, then merged: cheaper than a full sort when
        // a step adds a few hundred to a set of a million.
        const auto mid = m_items.begin() + static_cast<std::ptrdiff_t>(before);
        std::sort(mid, m_items.end());
        std::inplace_merge(m_items.begin(), mid, m_items.end());
    }
}

} // namespace hvi::solver
