#include "solver/BinnedWork.hpp"

#include "core/Parallel.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <omp.h>

namespace hvi::solver {

int BinnedWork::binOf(double ratio) {
    // floor(log2(ratio)) for ratio in [1, 2^kMaxBin), 0 below, kMaxBin above, for +inf and
    // for NaN: the number of bin edges 2^b (b = 1 .. kMaxBin) that ratio is not below (the
    // rule add() counts in lanes).
    int bin = 0;
    for (int b = 1; b <= kMaxBin; ++b) {
        bin += ratio < kBinEdge[static_cast<std::size_t>(b)] ? 0 : 1;
    }
    return bin;
}

void BinnedWork::add(std::span<const double> pointSteps, double smallestStep) {
    if (!(smallestStep > 0.0) || !std::isfinite(smallestStep)) {
        return;
    }
    // For each edge, the points not below it, summed as integers: exact, so any thread count
    // gives the same sums; a point is in bin k when it passes edges 1 .. k and not k + 1.
    // Counting edges instead of filling a histogram lets the loop run in vector lanes.
    std::array<std::size_t, kMaxBin + 1> passed{};
    const std::size_t n = pointSteps.size();
    const double* steps = pointSteps.data();
#pragma omp parallel if (n > kParallelMinItems)
    {
        // This thread's block of the points (static, as `omp for` would cut it).
        const auto threads = static_cast<std::size_t>(omp_get_num_threads());
        const auto me = static_cast<std::size_t>(omp_get_thread_num());
        const std::size_t first = n * me / threads, last = n * (me + 1) / threads;
        std::size_t p1 = 0, p2 = 0, p3 = 0, p4 = 0, p5 = 0, p6 = 0;
#pragma omp simd reduction(+ : p1, p2, p3, p4, p5, p6)
        for (std::size_t k = first; k < last; ++k) {
            const double ratio = steps[k] / smallestStep;
            p1 += ratio < kBinEdge[1] ? 0 : 1;
            p2 += ratio < kBinEdge[2] ? 0 : 1;
            p3 += ratio < kBinEdge[3] ? 0 : 1;
            p4 += ratio < kBinEdge[4] ? 0 : 1;
            p5 += ratio < kBinEdge[5] ? 0 : 1;
            p6 += ratio < kBinEdge[6] ? 0 : 1;
        }
#pragma omp critical(hviBinnedWorkCount)
        {
            passed[1] += p1;
            passed[2] += p2;
            passed[3] += p3;
            passed[4] += p4;
            passed[5] += p5;
            passed[6] += p6;
        }
    }
    static_assert(kMaxBin == 6, "one counter per bin edge above");
    passed[0] = n;
    double binned = 0.0;
    for (std::size_t b = 0; b <= kMaxBin; ++b) {
        const std::size_t inBin = b < kMaxBin ? passed[b] - passed[b + 1] : passed[b];
        binned += std::ldexp(static_cast<double>(inBin), -static_cast<int>(b));
    }
    m_evaluated += static_cast<double>(n);
    m_binned += binned;
}

} // namespace hvi::solver
