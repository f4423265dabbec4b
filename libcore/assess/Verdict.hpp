// The verdict document (schemas/verdict.schema.json) of an assessment.
#pragma once

#include "assess/Assessment.hpp"

#include <nlohmann/json.hpp>

namespace hvi::assess {

/// Everything but "provenance", "expectation" and "pictures", which the tool adds.
nlohmann::json verdictJson(const Assessment& assessment);

} // namespace hvi::assess
