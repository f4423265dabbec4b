#include "assess/EnergyBudget.hpp"

#include <cmath>

namespace hvi::assess {

EnergyBudget energyBudget(const io::HistoryColumns& h) {
    EnergyBudget budget;
    budget.rows = h.timeUs.size();
    if (budget.rows == 0) {
        return budget;
    }
    std::size_t worst = 0;
    bool finite = true;
    for (std::size_t k = 0; k < budget.rows; ++k) {
        if (!std::isfinite(h.energyError[k])) {
            finite = false; // a non-finite row is the worst there is
            worst = k;
            break;
        }
        if (std::fabs(h.energyError[k]) > std::fabs(h.energyError[worst])) {
            worst = k;
        }
    }
    const std::size_t last = budget.rows - 1;
    if (finite) {
        budget.maxError = h.energyError[worst];
        budget.finalError = h.energyError[last];
    }
    budget.maxErrorTimeUs = h.timeUs[worst];
    budget.initialTotalEnergyJ = h.totalEnergy[0];
    budget.finalTotalEnergyJ = h.totalEnergy[last];
    budget.deletedEnergyJ = h.deletedEnergy[last];
    budget.initialMomentumZ = h.momentumZ[0];
    budget.finalMomentumZ = h.momentumZ[last];
    budget.historyMassLossMg = h.mass[0] - h.mass[last];
    return budget;
}

} // namespace hvi::assess
