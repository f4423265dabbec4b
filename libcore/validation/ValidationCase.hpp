// The hypervelocity-impact tests the toolkit's verdicts are measured against
// (docs/validation.md), read from the files shipped in data/validation/ (compiled in):
//   - thesis_cases.json: the source study's cases (its Tables IV-IX), with the NASA results;
//   - nasa_tests.json: the development set, 52 Whipple, 16 foam-panel and 48 honeycomb-panel
//     shots of S. Ryan's public test database (distributed with pyBLOSSUM), each citing its
//     original report.
// Each becomes one Case with the shield's parts, their materials, and the test's result.
// Where the source leaves a value open the Case says what is assumed (Case::assumptions),
// and material names the tables do not hold are mapped to the nearest entry, also stated.
//
// Case ids: the source study's as they are; development-set Whipple ids (WPL-xxxx) as they
// are, foam and honeycomb ids prefixed "foam-" and "hc-" (the database reuses ids across
// tables and with the source study).
// Units: mm, km/s, g/cm3, ksi (docs/conventions.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hvi::validation {

enum class Shield { Whipple, Foam, Honeycomb };

/// "whipple", "foam", "honeycomb".
const char* toString(Shield shield);

struct Plate {
    std::string material;
    double thicknessMm = 0.0;
};

struct Case {
    std::string id;
    std::string set; ///< "source_study" or "development"
    Shield shield = Shield::Whipple;
    std::string projectileMaterial;
    double projectileDensityGCm3 = 0.0;
    double diameterMm = 0.0;
    double velocityKmS = 0.0;
    Plate front;        ///< bumper or front facesheet
    double gapMm = 0.0; ///< Whipple standoff (bumper back to wall front) or core thickness
    Plate rear;         ///< rear wall or rear facesheet
    std::optional<double> rearYieldKsi;
    // Cores.
    std::string coreMaterial;
    double relativeDensityPercent = 0.0, ppi = 0.0; ///< foam
    std::optional<double> panelArealDensityGCm2;    ///< foam: measured (FOAM10 Table 1)
    double cellSizeMm = 0.0, foilThicknessMm = 0.0; ///< honeycomb
    std::string result;                             ///< "P" or "NP": the test's
    std::string source;                             ///< the original report
    std::vector<std::string> assumptions;
};

/// Every case of both files, the source study's first, in file order.
const std::vector<Case>& allCases();

/// The cases of a named selection: "source_study", "development", "all", or "quick" (the
/// bracketing P/NP pairs that run in minutes: A1076/A1077 and HITF03147-2/-3), or "ci" (one
/// foam panel and one Whipple shield, HITF03147-2 and A1076, for the CI check). Throws
/// std::invalid_argument for another name.
std::vector<Case> selectCases(const std::string& selection);

/// The same cases with the shield types taken in turn (Whipple, foam, honeycomb, Whipple, ...),
/// each type in its given order: the run order of `make validate`, so that a validation
/// stopped part-way has measured every shield type rather than the first one only.
std::vector<Case> interleavedByShield(const std::vector<Case>& cases);

/// The case with this id; throws std::invalid_argument naming the id when there is none.
const Case& findCase(const std::string& id);

} // namespace hvi::validation
