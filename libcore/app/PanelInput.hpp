// The input of a scene writer (foam2layers, hcomb2rings), read once for both tools:
//
//   1. the input file (or stdin "-", or nothing: then the flags alone make the document);
//   2. a sizing.json written by ble-size (provenance.tool == "ble-size") is turned into the
//      tool's own document: its `threat` and `panel` blocks are kept (pointers stay the
//      same, so errors still point into the sizing file), BLE-only keys are dropped, every
//      other block is ignored;
//   3. the flags are written over the document (FlagOverlay);
//   4. the document is validated against the tool's schema (every issue at once, labelled
//      with the file or "<flags>"), and the schema defaults are filled in;
//   5. checks a schema cannot make, again all at once: facesheets given either as
//      facesheet_mm or as front_/rear_facesheet_mm (a single wall has the rear one only), a
//      core thicker than the two facesheets together (a thinner one is not a sandwich panel:
//      most likely a unit or key mix-up), and material names the toolkit knows.
//
// The result holds the resolved document (what the scene's provenance records: defaults
// filled, facesheets as front_ and rear_facesheet_mm) and typed views of the shared parts.
#pragma once

#include "app/FlagOverlay.hpp"
#include "app/InputOrigin.hpp"
#include "geometry/SceneBuilder.hpp"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hvi::app {

/// What distinguishes the two tools' inputs.
struct PanelInputKind {
    std::string schemaName;      ///< embedded schema, e.g. "foam_panel"
    std::vector<std::string> sizingPanelTypes; ///< ble-size panel types read ("foam_sandwich")
    std::string otherTypesHint;  ///< e.g. "hcomb2rings reads honeycomb_sandwich panels"
    std::string defaultId;       ///< id when neither the input nor its file name gives one
    std::vector<std::string> sizingPanelDrops; ///< ble-size panel keys the scene has no use for
    std::vector<std::pair<std::string, std::string>> sizingPanelRenames; ///< ble-size key -> ours
    std::vector<std::string> materialPointers; ///< material names to check against the table
};

struct PanelInput {
    nlohmann::json resolved; ///< the input with flags and defaults, facesheets normalised
    InputOrigin origin;
    std::string inputFile;          ///< as given; "" when the flags alone made the input
    bool fromSizing = false;        ///< the input was a ble-size sizing.json
    std::vector<std::string> notes; ///< values read but not used, for the tool to warn about

    /// The number at `pointer` in `resolved`, or kMissing (NaN) when absent.
    double number(const std::string& pointer) const;
    /// The string at `pointer` in `resolved`, or `fallback` when absent.
    std::string text(const std::string& pointer, const std::string& fallback = "") const;

    std::string id() const { return text("/id", "scene"); }
    geometry::ThreatSpec threat() const;
    geometry::PanelFrame frame() const;
    geometry::SceneNumerics numerics() const;
};

/// Steps 1-5 of the file comment. Throws InputError (exit code 2) naming file or "<flags>",
/// pointer and expectation for every problem found.
PanelInput loadPanelInput(const std::string& inputFile, const PanelInputKind& kind,
                          const FlagOverlay& flags);

} // namespace hvi::app
