// foam2layers: a foam-core sandwich panel -> a 2D axisymmetric impact scene for hvi-run.
// The foam core becomes a mass-conserved stack of flat layers with the effective PPI
// (geometry/FoamLayerStack.hpp); projectile, facesheets, numerics, domain radius and end time
// come from geometry/SceneBuilder.hpp. Input: schemas/foam_panel.schema.json or a ble-size
// sizing.json with a foam_sandwich panel; flags can give or override every value.
#pragma once

#include "app/SceneWriterTool.hpp"

namespace hvi::app {

/// What foam2layers reads (schema, ble-size panel type, material keys).
PanelInputKind foamPanelInputKind();

/// The scene of a resolved foam panel input (in-process entry point; the tool adds nothing
/// but writing). Throws InputError located in the input for a core the reduction rejects.
SceneResult buildFoamScene(const PanelInput& input, const nlohmann::json& provenance);

class Foam2LayersTool : public SceneWriterTool {
public:
    Foam2LayersTool();

protected:
    void addCoreOptions(CLI::App& app, FlagOverlay& flags) override;
    SceneResult buildScene(const PanelInput& input,
                           const nlohmann::json& provenance) const override {
        return buildFoamScene(input, provenance);
    }
};

} // namespace hvi::app
