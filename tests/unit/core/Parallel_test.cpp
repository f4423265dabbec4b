// compactIndices (core/Parallel.hpp): the kept indices, ascending, the same list as a serial
// filter at one and two threads, below and above the threading threshold, kept sets empty,
// full and sparse.
#include "core/Parallel.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <omp.h>
#include <vector>

namespace {

std::vector<int32_t> serialFilter(std::size_t count, bool (*keep)(std::size_t)) {
    std::vector<int32_t> out;
    for (std::size_t k = 0; k < count; ++k) {
        if (keep(k)) {
            out.push_back(static_cast<int32_t>(k));
        }
    }
    return out;
}

bool everySeventhOrTail(std::size_t k) { return k % 7 == 3 || k + 5 > 12345; }
bool none(std::size_t) { return false; }
bool all(std::size_t) { return true; }

TEST(CompactIndices, TheSerialFilterAtAnyThreadCount) {
    for (const std::size_t count : {std::size_t{0}, std::size_t{100}, hvi::kParallelMinItems + 1,
                                    std::size_t{12345}}) {
        for (bool (*keep)(std::size_t) : {everySeventhOrTail, none, all}) {
            const auto expected = serialFilter(count, keep);
            for (const int threads : {1, 2}) {
                omp_set_num_threads(threads);
                std::vector<int32_t> out(3, -1); // stale contents are replaced
                hvi::compactIndices(count, keep, out);
                EXPECT_EQ(out, expected) << count << " items, " << threads << " threads";
            }
        }
    }
    omp_set_num_threads(1);
}

} // namespace
