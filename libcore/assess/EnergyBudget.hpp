// Conservation figures of a run from its /history (docs/metrics.md, "Energy error").
//
// energy_error is the EnergyError history column (OutputFields.hpp: (E + E_deleted - E0) /
// |E0|, energy carried away by deleted particles and eroded elements counted as accounted
// for) at the row where its magnitude is largest: the worst moment of the run, independent of
// how often snapshots were written. The final value, the initial total energy, the deleted
// energy and the axial-momentum change are reported beside it.
#pragma once

#include "io/OutputFields.hpp"

#include <cstddef>
#include <optional>

namespace hvi::assess {

struct EnergyBudget {
    std::size_t rows = 0;
    std::optional<double> maxError; ///< signed value of largest magnitude [-]
    std::optional<double> maxErrorTimeUs;
    std::optional<double> finalError; ///< [-]
    std::optional<double> initialTotalEnergyJ, finalTotalEnergyJ, deletedEnergyJ;
    std::optional<double> initialMomentumZ, finalMomentumZ; ///< [mg km/s]
    std::optional<double> historyMassLossMg;                ///< Mass[0] - Mass[last]
};

/// Nothing but `rows` is set when the history is empty.
EnergyBudget energyBudget(const io::HistoryColumns& history);

} // namespace hvi::assess
