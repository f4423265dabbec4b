#include "solver/BinnedWork.hpp"

#include "core/Parallel.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace hvi::solver {

int BinnedWork::binOf(double ratio) {
    if (!(ratio < kTopRatio)) { // +inf and NaN too
        return kMaxBin;
    }
    // floor(log2(ratio)) for ratio in [1, 2^kMaxBin), 0 below: one comparison per bin, which
    // the loop in add() runs without a call (ilogb was 1.6 % of a Whipple shot's profile).
    int bin = 0;
    for (int b = 1; b < kMaxBin; ++b) {
        bin += ratio >= kBinRatio[static_cast<std::size_t>(b)] ? 1 : 0;
    }
    return bin;
}

void BinnedWork::add(std::span<const double> pointSteps, double smallestStep) {
    if (!(smallestStep > 0.0) || !std::isfinite(smallestStep)) {
        return;
    }
    // A count per bin, summed as integers: exact, so any thread count gives the same sum.
    std::array<std::size_t, kMaxBin + 1> count{};
    const std::size_t n = pointSteps.size();
#pragma omp parallel if (n > kParallelMinItems)
    {
        std::array<std::size_t, kMaxBin + 1> local{};
#pragma omp for schedule(static) nowait
        for (std::size_t k = 0; k < n; ++k) {
            ++local[static_cast<std::size_t>(binOf(pointSteps[k] / smallestStep))];
        }
#pragma omp critical(hviBinnedWorkCount)
        for (std::size_t b = 0; b <= kMaxBin; ++b) {
            count[b] += local[b];
        }
    }
    double binned = 0.0;
    for (std::size_t b = 0; b <= kMaxBin; ++b) {
        binned += std::ldexp(static_cast<double>(count[b]), -static_cast<int>(b));
    }
    m_evaluated += static_cast<double>(n);
    m_binned += binned;
}

} // namespace hvi::solver
