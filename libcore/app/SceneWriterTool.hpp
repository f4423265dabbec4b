// The common skeleton of the two scene writers (foam2layers, hcomb2rings): a Tool that reads
// a panel (PanelInput), reduces its core (the derived tool), assembles the scene
// (geometry::SceneBuilder), checks it against schemas/scene.schema.json, reports it on
// stderr, and writes it, with an optional gmsh mesh of its FE bodies, atomically.
//
// Options every scene writer has: INPUT (positional, optional: without it the flags make the
// whole input; "-" reads stdin), -o/--output (default "-", stdout), --mesh, and flags for
// the threat and the numerics. A derived tool adds the flags of its panel and core.
#pragma once

#include "app/FlagOverlay.hpp"
#include "app/PanelInput.hpp"
#include "geometry/GmshMesher.hpp"
#include "tool/Tool.hpp"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hvi::app {

/// What a derived tool builds from a resolved input.
struct SceneResult {
    nlohmann::json scene;              ///< the complete scene document (provenance included)
    std::vector<std::string> warnings; ///< one line each, with the numbers and the remedy
    std::vector<std::string> report;   ///< the stderr summary, one line each
    std::vector<geometry::MeshRectangle> feRectangles; ///< the FE bodies, for --mesh
};

/// Adds the flags every scene writer shares (threat, facesheets, numerics) to `flags`.
void addSharedSceneFlags(CLI::App& app, FlagOverlay& flags);

/// The summary lines common to both tools (domain radius, end time, discretisations).
std::vector<std::string> sharedReport(const geometry::SceneBuilder& builder);

/// "+0.000 %": a relative difference as a signed percentage with 3 decimals.
std::string formatPercent(double relative);

class SceneWriterTool : public tool::Tool {
public:
    SceneWriterTool(std::string name, std::string summary, PanelInputKind kind);

protected:
    void addOptions(CLI::App& app) final;
    void execute() final;
    std::string inputSchemaName() const final { return m_kind.schemaName; }

    /// The derived tool's own flags (panel and core).
    virtual void addCoreOptions(CLI::App& app, FlagOverlay& flags) = 0;
    /// Builds the scene from the resolved input; `provenance` goes into the scene as is.
    virtual SceneResult buildScene(const PanelInput& input,
                                   const nlohmann::json& provenance) const = 0;

private:
    PanelInputKind m_kind;
    FlagOverlay m_flags;
    std::string m_input;
    std::string m_output = "-";
    bool m_mesh = false;
};

} // namespace hvi::app
