// hcomb2rings: a honeycomb-core sandwich panel -> a 2D axisymmetric impact scene for
// hvi-run. The honeycomb core becomes concentric rings of the core height at the radii where
// a ray from the impact point crosses the cell walls (geometry/HoneycombRings.hpp); the rings
// carry less mass than the real core by design, and the scene's summary says how much.
// Projectile, facesheets, numerics, domain radius and end time come from
// geometry/SceneBuilder.hpp. Input: schemas/honeycomb_panel.schema.json or a ble-size
// sizing.json with a honeycomb_sandwich panel; flags can give or override every value.
#pragma once

#include "app/SceneWriterTool.hpp"

namespace hvi::app {

/// What hcomb2rings reads (schema, ble-size panel type, material keys).
PanelInputKind honeycombPanelInputKind();

/// The scene of a resolved honeycomb panel input (in-process entry point).
SceneResult buildHoneycombScene(const PanelInput& input, const nlohmann::json& provenance);

class Hcomb2RingsTool : public SceneWriterTool {
public:
    Hcomb2RingsTool();

protected:
    void addCoreOptions(CLI::App& app, FlagOverlay& flags) override;
    SceneResult buildScene(const PanelInput& input,
                           const nlohmann::json& provenance) const override {
        return buildHoneycombScene(input, provenance);
    }
};

} // namespace hvi::app
