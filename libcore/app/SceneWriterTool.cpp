#include "app/SceneWriterTool.hpp"

#include "core/Error.hpp"
#include "geometry/InputChecks.hpp"
#include "io/AtomicOutput.hpp"
#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"
#include "scene/Defaults.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

namespace hvi::app {

namespace fs = std::filesystem;
using geometry::formatNumber;
using nlohmann::json;

void addSharedSceneFlags(CLI::App& app, FlagOverlay& flags) {
    flags.addNumber(app, "--diameter-mm", "/threat/diameter_mm",
                    "Projectile diameter [mm], 0 < value <= 1000");
    flags.addNumber(app, "--velocity-km-s", "/threat/velocity_km_s",
                    "Impact speed along the panel normal [km/s], 0 < value <= 100");
    flags.addString(app, "--projectile-material", "/threat/material",
                    "Projectile material name (default Al6061-T6)");
    auto* both = flags.addNumber(app, "--facesheet-mm", "/panel/facesheet_mm",
                                 "Thickness of both facesheets [mm], > 0",
                                 {"/panel/front_facesheet_mm", "/panel/rear_facesheet_mm"});
    auto* front = flags.addNumber(app, "--front-facesheet-mm", "/panel/front_facesheet_mm",
                                  "Front (impact-side) facesheet thickness [mm], > 0");
    auto* rear = flags.addNumber(app, "--rear-facesheet-mm", "/panel/rear_facesheet_mm",
                                 "Rear facesheet thickness [mm], > 0");
    both->excludes(front);
    both->excludes(rear);
    flags.addNumber(app, "--standoff-mm,--core-thickness-mm", "/panel/core_thickness_mm",
                    "Core thickness = standoff S between the facesheets [mm], > front + rear "
                    "facesheet");
    flags.addString(app, "--material", "/panel/material",
                    "Panel material name: facesheets, and the foam or (by default) the "
                    "honeycomb foil (default Al6061-T6)");
    flags.addString(app, "--front-facesheet-material", "/panel/front_facesheet_material",
                    "Front facesheet (bumper) material (default: --material)");
    flags.addString(app, "--rear-facesheet-material", "/panel/rear_facesheet_material",
                    "Rear facesheet (rear wall) material (default: --material)");
    flags.addNumber(app, "--particle-spacing-mm", "/numerics/particle_spacing_mm",
                    "SPH particle spacing and FE element size [mm], > 0 (default: the calibrated " +
                        scene::defaultText(scene::kDefaultParticleSpacingMm) + ")");
    flags.addNumber(app, "--erosion-factor", "/numerics/erosion_factor",
                    "FE erosion threshold on geometric strain [-], > 0 (default: the calibrated " +
                        scene::defaultText(scene::kDefaultErosionFactor) + ")");
    flags.addString(app, "--core-discretization", "/numerics/core_discretization",
                    "Core bodies as fe (default) or sph; sph (the rear wall follows) gives an "
                    "all-SPH scene, which is what hvi-run can run until its FE solver lands",
                    {"fe", "sph"});
    flags.addString(app, "--rear-wall-discretization", "/numerics/rear_wall_discretization",
                    "Rear facesheet as fe or sph (default: as the core)", {"fe", "sph"});
    flags.addNumber(app, "--end-time-us", "/numerics/end_time_us",
                    "Simulated end time [us], > 0 (default: 2 L/V + 5 us rounded up, L = "
                    "projectile nose to the back of the rear wall)");
    flags.addNumber(app, "--domain-radius-mm", "/numerics/domain_radius_mm",
                    "Outer radius of the axisymmetric domain [mm], > 0 (default: max(2 x the "
                    "17 deg debris-cone footprint on the rear wall, 5 projectile diameters), "
                    "rounded up to whole mm)");
    flags.addString(app, "--id", "/id", "Case identifier written into the scene");
}

std::string formatPercent(double relative) {
    // Rounding noise (-1e-16) must not print as "-0.000 %".
    const double percent = std::fabs(relative) < 5e-6 ? 0.0 : 100.0 * relative;
    char text[64];
    std::snprintf(text, sizeof text, "%+.3f %%", percent);
    return text;
}

std::vector<std::string> sharedReport(const geometry::SceneBuilder& builder) {
    const auto& numerics = builder.numerics();
    const auto& frame = builder.frame();
    const std::string wall =
        " mm (rear wall, " + std::string(geometry::toString(numerics.rearWallDiscretization)) + ")";
    return {(frame.bumper
                 ? "facesheets " + formatNumber(frame.frontFacesheetMm) + " mm (bumper, sph) and " +
                       formatNumber(frame.rearFacesheetMm) + wall + ", core " +
                       std::string(geometry::toString(numerics.coreDiscretization))
                 : "single wall " + formatNumber(frame.rearFacesheetMm) + wall) +
                ", particle spacing " + formatNumber(numerics.particleSpacingMm) + " mm",
            "domain radius " + formatNumber(builder.domainRadius().value) + " mm (" +
                (std::isnan(numerics.domainRadiusMm) ? "rule" : "given") + "), end time " +
                formatNumber(builder.endTime().value) + " us (" +
                (std::isnan(numerics.endTimeUs) ? "rule" : "given") + ")"};
}

SceneWriterTool::SceneWriterTool(std::string name, std::string summary, PanelInputKind kind)
    : Tool(std::move(name), std::move(summary)), m_kind(std::move(kind)) {}

void SceneWriterTool::addOptions(CLI::App& app) {
    app.add_option("input", m_input,
                   "Input JSON: a panel file (schema " + m_kind.schemaName +
                       ", see --print-schema) or a sizing.json written by ble-size; '-' reads "
                       "stdin; without it the flags give the whole input")
        ->type_name("INPUT.json");
    auto* output =
        app.add_option("-o,--output", m_output, "Scene file to write ('-' = stdout)")
            ->type_name("SCENE.json")
            ->capture_default_str()
            ->check(CLI::Validator(
                [](std::string& value) {
                    return fs::path(value).extension() == ".msh"
                               ? std::string("the scene file cannot end in .msh (--mesh writes "
                                             "SCENE.msh next to it)")
                               : std::string();
                },
                "", "scene name"));
    app.add_flag("--mesh", m_mesh,
                 "Also write SCENE.msh next to the scene: a structured quad mesh (gmsh, MSH 4.1, "
                 "x = z, y = r, mm) of every FE body at its element size, to look at")
        ->needs(output);
    addCoreOptions(app, m_flags);
    addSharedSceneFlags(app, m_flags);
    for (const auto& [option, pointer] : m_flags.numberFlags()) {
        flagSetsPointer(option, pointer);
    }
    app.footer("Values given by flags override the input file; their errors are reported as "
               "'<flags>: /pointer: ...'.\n" +
               app.get_footer());
}

void SceneWriterTool::execute() {
    const PanelInput input = loadPanelInput(m_input, m_kind, m_flags);
    for (const auto& note : input.notes) {
        warn(note);
    }
    const json prov = provenance(
        input.inputFile.empty() ? std::string(kFlagsLabel) : input.inputFile, input.resolved);
    const SceneResult result = buildScene(input, prov);
    if (m_mesh && result.feRectangles.empty()) {
        throw InputError(kFlagsLabel, "/numerics/core_discretization",
                         "--mesh given, but the scene has no FE body (core and rear wall are sph)",
                         "--mesh with core_discretization or rear_wall_discretization fe");
    }
    try {
        io::validateAgainstSchema(result.scene, "scene", "<scene>");
    } catch (const InputError& e) {
        throw RuntimeFailure(std::string("the scene built does not match "
                                         "schemas/scene.schema.json (a bug): ") +
                             e.what());
    }

    for (const auto& warning : result.warnings) {
        warn(warning);
    }
    for (const auto& line : result.report) {
        info(line);
    }

    std::optional<io::AtomicOutput> meshOut;
    geometry::MeshCounts counts;
    if (m_mesh) {
        meshOut.emplace(fs::path(m_output).replace_extension(".msh"));
        counts = geometry::GmshMesher::write(result.feRectangles, meshOut->tempPath());
    }
    io::AtomicOutput sceneOut(m_output);
    {
        std::ofstream out(sceneOut.tempPath(), std::ios::binary);
        out << io::jsonText(result.scene, 2) << "\n";
        out.flush();
        if (!out) {
            throw RuntimeFailure("cannot write " + sceneOut.tempPath().string());
        }
    }
    sceneOut.commit();
    if (meshOut) {
        meshOut->commit();
        info("wrote " + meshOut->finalPath().string() + ": " + std::to_string(counts.elements) +
             " quadrilaterals, " + std::to_string(counts.nodes) + " nodes");
    }
    if (!sceneOut.isStdout()) {
        info("wrote " + sceneOut.finalPath().string());
    }
}

} // namespace hvi::app
