// hvi-assess --expect: compare a verdict with an expected outcome (docs/metrics.md,
// "Expectations").
//
// The expectation file may be
//   - an expected block: {"pnp": "NP", "bumper_hole_diameter_mm": 6.7, "tolerances": {...}}
//     (schemas/expected.schema.json);
//   - one case: {"id": "UM-3.125", ..., "expected": {...}};
//   - a collection of cases anywhere in a document, such as data/validation/
//     thesis_cases.json: the case is picked by --case ID, or else by the run's scene id.
// Each metric present (and not null) in the block is compared: pnp exactly, numbers with
// |actual - expected| <= atol + rtol * |expected| (defaults below, overridable per metric in
// the block's "tolerances").
#pragma once

#include "assess/Assessment.hpp"

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace hvi::assess {

/// Default tolerances, with the reasons in docs/metrics.md.
struct DefaultTolerances {
    /// The source study's particle-size study: 3 % error at 0.015 mm, 11 % at 0.02 mm; 10 %
    /// separates a calibrated run from a coarse one. Plus two sampling intervals (the hole edge
    /// is located to within one spacing on each side).
    static constexpr double holeRtol = 0.10;
    static constexpr double holeAtolBins = 2.0;
    /// Depth is quantised by the layer pitch of the reduced core: one pitch of the 10 PPI,
    /// 2 in core (5.08 mm) is 12 % of the measured 41.4 mm of HITF04151; 15 % allows one layer.
    static constexpr double depthRtol = 0.15;
    static constexpr double widthRtol = 0.20;
};

/// The expected block picked from an expectation document.
struct ExpectedBlock {
    nlohmann::json block;
    std::optional<std::string> caseId;
    std::string pointer; ///< where the block is in the file ("" = the whole document)
    std::string file;
};

/// Picks and validates the expected block. Throws InputError (file, pointer) when there is
/// none, when --case names no case, or when the block is invalid.
ExpectedBlock selectExpected(const nlohmann::json& document, const std::string& file,
                             const std::optional<std::string>& caseId, const std::string& sceneId);

struct ExpectationCheck {
    std::string quantity;
    nlohmann::json expected, actual;
    std::optional<double> difference, allowed;
    bool passed = false;
};

struct Expectation {
    std::optional<std::string> caseId;
    std::string source;
    bool passed = true;
    std::vector<ExpectationCheck> checks;

    /// "expect CASE: PASS: pnp NP (expected NP) ok; bumper_hole_diameter_mm 6.52 (expected
    /// 6.7, diff -0.18, allowed 0.73) ok"
    std::string reportLine() const;
    nlohmann::json toJson() const;
};

/// Compares; `only` (if not empty) restricts the checks to these quantities.
Expectation compareWithExpected(const ExpectedBlock& expected, const Assessment& assessment,
                                const std::set<std::string>& only = {});

} // namespace hvi::assess
