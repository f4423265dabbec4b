// ble-size's computation: from a resolved constraints document (schemas/constraints.schema.json,
// defaults filled in) to the sizing document (schemas/sizing.schema.json), the ballistic limit
// curve and the validity warnings. No I/O here, so tests call it in-process.
//
// File units (mm, km/s, MPa or ksi) are converted to the JSC equations' units (cm, g/cm^3,
// km/s, ksi) here and nowhere else.
#pragma once

#include "ble/Ble.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace hvi::app {

struct BleSizingOutcome {
    nlohmann::json sizing;          ///< the sizing document, without provenance
    ble::BallisticLimitCurve curve; ///< d_c(V) for the (given or designed) shield
    bool hasCurve = false;          ///< false when the shield is not fully defined
    std::string curveLabel;         ///< e.g. "Whipple NNO, t_b 2.03 mm, ..."
    std::vector<ble::ValidityWarning> warnings;
};

/// Computes everything. `file` names the input in error messages. Throws InputError for
/// semantic problems the schema cannot see (unknown material, missing thickness in
/// performance mode, both yield units given), each with its JSON pointer; RuntimeFailure
/// when a result is NaN or infinite (it names the result).
BleSizingOutcome computeSizing(const nlohmann::json& resolved, const std::string& file);

} // namespace hvi::app
