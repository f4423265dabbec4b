#include "solver/BinnedWork.hpp"

#include <cmath>

namespace hvi::solver {

int BinnedWork::binOf(double ratio) {
    if (!(ratio < std::ldexp(1.0, kMaxBin))) { // +inf and NaN too
        return kMaxBin;
    }
    if (ratio < 2.0) {
        return 0;
    }
    return std::ilogb(ratio); // floor(log2(ratio)) for ratio >= 1
}

void BinnedWork::add(std::span<const double> pointSteps, double smallestStep) {
    if (!(smallestStep > 0.0) || !std::isfinite(smallestStep)) {
        return;
    }
    double binned = 0.0;
    for (const double step : pointSteps) {
        binned += std::ldexp(1.0, -binOf(step / smallestStep));
    }
    m_evaluated += static_cast<double>(pointSteps.size());
    m_binned += binned;
}

} // namespace hvi::solver
