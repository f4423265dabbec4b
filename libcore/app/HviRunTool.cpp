#include "app/HviRunTool.hpp"

#include "app/BuiltinCases.hpp"
#include "app/RunScene.hpp"
#include "geometry/GmshMesher.hpp"
#include "io/Checkpoint.hpp"
#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"
#include "io/RunLock.hpp"
#include "scene/PointBudget.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneLibrary.hpp"
#include "solver/RunLoop.hpp"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <omp.h>
#include <sstream>
#include <utility>

namespace hvi::app {

using nlohmann::json;

namespace {
extern "C" void onSignal(int) {
    solver::g_stopRequested.store(true);
}

/// The wall time booked so far to a named section of a package's phases [s] (0 if none).
double sectionSeconds(const solver::Simulation& sim, std::string_view package,
                      std::string_view section) {
    for (const auto& [name, times] : sim.packageTimes()) {
        if (name != package) {
            continue;
        }
        for (const auto& [part, seconds] : times.sections()) {
            if (part == section) {
                return seconds;
            }
        }
    }
    return 0.0;
}

/// The run file's name: -o, or the scene's with .h5. A scene read from stdin has no name to
/// put the run file beside.
std::string runFileName(const std::string& scene, const std::string& output) {
    if (!output.empty()) {
        return output;
    }
    if (scene == "-") {
        throw InputError("<flags>", "--output", "is needed when the scene comes from stdin",
                         "-o RUN.h5");
    }
    return std::filesystem::path(scene).replace_extension(".h5").string();
}

/// Refuses a run whose outputs would replace its own scene: the run file itself, or the
/// XDMF, mesh and checkpoint files written beside it. The run file is written to a
/// temporary and renamed, so the scene would be gone without a word.
void refuseToOverwriteScene(const std::string& scene, const std::string& output) {
    if (scene == "-") {
        return;
    }
    const std::filesystem::path run(output);
    const std::pair<std::filesystem::path, const char*> written[] = {
        {run, "the run file"},
        {std::filesystem::path(run).replace_extension(".xmf"), "the run's XDMF sidecar"},
        {std::filesystem::path(run).replace_extension(".msh"), "the run's FE mesh"},
        {io::checkpointPathFor(run), "the run's checkpoint"},
        {io::lockPathFor(run), "the run's lock"}};
    for (const auto& [path, what] : written) {
        std::error_code error; // a file that does not exist yet is not the scene
        if (std::filesystem::equivalent(scene, path, error)) {
            throw InputError(
                "<flags>", "--output",
                "would replace the scene " + scene + " with " + what + " " + path.string(),
                "a run file whose name and whose .xmf, .msh, .ckpt.h5 and .lock are not "
                "the scene's");
        }
    }
}
} // namespace

HviRunTool::HviRunTool()
    : tool::Tool("hvi-run", "2D axisymmetric SPH + finite-element simulation of a "
                            "hypervelocity impact (Mie-Grueneisen EOS, Johnson-Cook strength "
                            "and failure, erosion, contact)") {}

void HviRunTool::addOptions(CLI::App& app) {
    app.add_option("scene", m_scene,
                   "Scene JSON (from foam2layers/hcomb2rings or by hand; '-' reads stdin, and "
                   "then -o is needed)")
        ->check(CLI::ExistingFile | CLI::IsMember({"-"}));
    app.add_option("-o,--output", m_output,
                   "Run file to write (HDF5; default SCENE.h5), with "
                   "an XDMF sidecar .xmf for ParaView");
    app.add_option("--threads", m_threads, "OpenMP threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--resolution-mm", m_resolution,
                   "Particle spacing and element size [mm] for every body (overrides the "
                   "scene)")
        ->check(CLI::PositiveNumber);
    app.add_option("--end-time-us", m_endTime, "Simulated time to stop at [us] (overrides)")
        ->check(CLI::PositiveNumber);
    app.add_option("--snapshot-every-us", m_snapshotEvery,
                   "Interval between field snapshots [us] (overrides)")
        ->check(CLI::PositiveNumber);
    app.add_option("--materials", m_materials,
                   "Extra material library JSON laid over the built-in one")
        ->check(CLI::ExistingFile);
    app.add_flag("--resume", m_resume,
                 "Continue from RUN.ckpt.h5 (left by an interrupted or checkpointed run), "
                 "keeping the snapshots up to it from RUN (or from the RUN.tmp.PID a run "
                 "killed outright left; refused when neither is there)");
    app.add_option("--checkpoint-every-s", m_checkpointEvery,
                   "Wall time between checkpoints [s] (0 = only on interrupt; default 300)")
        ->check(CLI::NonNegativeNumber);
    app.add_flag("--benchmark", m_benchmark,
                 "Measure particle-steps per second on the built-in bumper case (3.125 mm Al "
                 "sphere at 6.847 km/s on 0.8 mm Al; spacing --resolution-mm, default " +
                     scene::defaultText(scene::kDefaultParticleSpacingMm) + ")");
    app.add_option("--benchmark-steps", m_benchmarkSteps, "Steps timed by --benchmark")
        ->check(CLI::Range(1L, 100000000L));
    app.add_option("--benchmark-scene", m_benchmarkScene,
                   "Scenes timed by --benchmark: sph (all-SPH bumper), fe (FE bumper), or both")
        ->check(CLI::IsMember({"both", "sph", "fe"}));
    app.add_flag("--check", m_check,
                 "Read and check the scene (schema, materials, layout, point count against "
                 "memory), print what would run on stdout and exit without running");
    app.add_flag("--list-materials", m_listMaterials, "List the built-in materials and exit");
}

void HviRunTool::benchmark() {
    const double spacing = m_resolution > 0.0 ? m_resolution : scene::kDefaultParticleSpacingMm;
    const auto library = scene::sceneLibrary(json::object(), "<builtin>");
    // Two scenes: the all-SPH bumper case, and the same with the bumper as finite elements
    // (the element throughput; FE time only, contact reported apart).
    for (const bool feBumper : {false, true}) {
        if (m_benchmarkScene != "both" && (m_benchmarkScene == "fe") != feBumper) {
            continue;
        }
        json doc = bumperCaseScene(spacing);
        if (feBumper) {
            doc["bodies"][1]["discretization"] = "fe";
        }
        const scene::Scene scene = scene::parseScene(doc, "<benchmark>", library.names());
        scene::requirePointBudget(scene, "<benchmark>", scene::availableMemoryBytes());
        const auto tSetup = std::chrono::steady_clock::now();
        solver::Simulation sim(scene, library);
        const double setup =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - tSetup).count();
        // Warm-up: the first contact, so the timed steps see a developed impact.
        for (int k = 0; k < 20; ++k) {
            sim.advance();
        }
        double particleSteps = 0.0, activeSteps = 0.0, pairs = 0.0, elementSteps = 0.0;
        double insidePairs = 0.0, computedPairs = 0.0;
        const auto before = sim.packageSeconds();
        const double pairSecondsBefore = sectionSeconds(sim, "sph", "pair loops");
        const auto t0 = std::chrono::steady_clock::now();
        for (long k = 0; k < m_benchmarkSteps; ++k) {
            sim.advance();
            particleSteps += static_cast<double>(sim.aliveCount());
            activeSteps += static_cast<double>(sim.activeCount());
            pairs += static_cast<double>(sim.pairCount());
            insidePairs += static_cast<double>(sim.evaluatedPairs().inside);
            computedPairs += static_cast<double>(sim.evaluatedPairs().computed);
            if (sim.finiteElements()) {
                elementSteps += static_cast<double>(sim.finiteElements()->evaluatedCount());
            }
        }
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const auto after = sim.packageSeconds();
        const double pairSeconds = sectionSeconds(sim, "sph", "pair loops") - pairSecondsBefore;
        char line[1024];
        if (!feBumper) {
            std::snprintf(
                line, sizeof line,
                "benchmark: bumper case, spacing %.4f mm, %zu particles, %d threads, %ld steps "
                "in %.2f s (setup %.2f s)\n"
                "  particle-steps/s (all particles):    %.3e\n"
                "  particle-steps/s (active particles): %.3e  (%.0f %% of particles active)\n"
                "  neighbour pairs per active particle: %.1f listed, %.1f inside the support, "
                "%.1f computed (padded to the vector lanes)\n"
                "  pair loops: %.2f s (%.0f %% of the steps), %.3e computed pairs/s, %.1f "
                "GFLOP/s at %.0f flops a pair\n"
                "  simulated %.4f us, mean dt %.3e us, energy error %+.2e\n",
                spacing, sim.particles().size(), omp_get_max_threads(), m_benchmarkSteps, wall,
                setup, particleSteps / wall, activeSteps / wall,
                100.0 * activeSteps / std::max(particleSteps, 1.0),
                pairs / std::max(activeSteps, 1.0), insidePairs / std::max(activeSteps, 1.0),
                computedPairs / std::max(activeSteps, 1.0), pairSeconds,
                100.0 * pairSeconds / wall, computedPairs / std::max(pairSeconds, 1e-12),
                computedPairs * sph::kPairFlops / std::max(pairSeconds, 1e-12) / 1e9,
                sph::kPairFlops, sim.time(),
                sim.time() / static_cast<double>(sim.step()), sim.energyError());
        } else {
            const double feSeconds = after.fe - before.fe;
            const double contactSeconds = after.contact - before.contact;
            const double sphSeconds = after.sph - before.sph;
            // Like for like: the time per element the FE update evaluated against the time
            // per particle the SPH packages evaluated (dormant ones cost neither).
            const double elementRate = elementSteps / std::max(feSeconds, 1e-12);
            const double activeRate = activeSteps / std::max(sphSeconds, 1e-12);
            std::snprintf(
                line, sizeof line,
                "benchmark: SPH projectile on an FE bumper, %zu particles, %zu elements, %d "
                "threads, %ld steps in %.2f s (setup %.2f s)\n"
                "  element-steps/s (evaluated elements, FE time %.2f s): %.3e  (%.0f elements "
                "evaluated per step)\n"
                "  particle-steps/s (all particles, SPH time %.2f s):     %.3e\n"
                "  particle-steps/s (active particles, SPH time):        %.3e\n"
                "  an element-step costs %.2f of an active particle-step\n"
                "  contact: %.2f s (%.0f %% of the step)\n"
                "  simulated %.4f us, mean dt %.3e us, energy error %+.2e, %zu elements eroded\n",
                sim.particles().size(), sim.finiteElements()->elements().size(),
                omp_get_max_threads(), m_benchmarkSteps, wall, setup, feSeconds, elementRate,
                elementSteps / static_cast<double>(m_benchmarkSteps), sphSeconds,
                particleSteps / std::max(sphSeconds, 1e-12), activeRate,
                activeRate / std::max(elementRate, 1e-12), contactSeconds,
                100.0 * contactSeconds / wall, sim.time(),
                sim.time() / static_cast<double>(sim.step()), sim.energyError(),
                sim.finiteElements()->erodedCount());
        }
        std::cout << line << std::flush;
    }
}

RunScene HviRunTool::loadScene() const {
    RunScene loaded = loadRunScene(m_scene, {m_resolution, m_endTime, m_snapshotEvery, m_materials},
                                   scene::availableMemoryBytes());
    for (const auto& w : loaded.warnings) {
        warn(m_scene + ": " + w);
    }
    return loaded;
}

void HviRunTool::checkScene() const {
    const RunScene loaded = loadScene();
    const scene::Scene& scene = loaded.scene;
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: scene '%s' can run: %zu bodies, about %.0f points (%.0f MB of %.0f MB "
                  "available), spacing %g mm, to %g us\n",
                  m_scene.c_str(), scene.id.c_str(), scene.bodies.size(), loaded.estimatedPoints,
                  loaded.estimatedPoints * scene::kBytesPerPoint / 1e6,
                  loaded.memoryLimitBytes / 1e6, scene.sph.particleSpacing, scene.run.endTime);
    std::cout << line << std::flush;
}

void HviRunTool::execute() {
    if (m_threads > 0) {
        omp_set_num_threads(m_threads);
    }
    if (m_listMaterials) {
        for (const auto& name : scene::sceneLibrary(json::object(), "<builtin>").names()) {
            std::cout << name << "\n";
        }
        return;
    }
    if (m_benchmark) {
        benchmark();
        return;
    }
    if (m_scene.empty()) {
        throw InputError("<flags>", "", "no scene file given", "hvi-run SCENE.json [-o RUN.h5]");
    }
    if (m_check) {
        checkScene();
        return;
    }
    const std::string output = runFileName(m_scene, m_output);
    refuseToOverwriteScene(m_scene, output);
    const io::RunLock lock(output); // one hvi-run per -o, until this one exits
    // --resume without a checkpoint would start afresh and overwrite what is there.
    if (m_resume && !std::filesystem::exists(io::checkpointPathFor(output))) {
        throw InputError("<flags>", "--resume",
                         "no checkpoint " + io::checkpointPathFor(output).string() +
                             " to continue from",
                         "the checkpoint an interrupted run of this -o left, or no --resume");
    }
    const RunScene loaded = loadScene();
    const scene::Scene& scene = loaded.scene;
    const material::MaterialLibrary& library = loaded.library;

    solver::Simulation sim(scene, library);
    json materials = json::object();
    for (const auto& body : scene.bodies) {
        const auto& spec = library.get(body.material);
        materials[body.material] =
            json::parse(spec.definitionJson.empty() ? "{}" : spec.definitionJson);
    }
    const int threads = omp_get_max_threads();
    json prov = provenance(m_scene, scene.resolved);
    prov["threads"] = threads;
    // The FE mesh beside the run, for inspection in gmsh (the same structured grid). Written
    // once the run has ended (complete or interrupted), so a run that fails or a refused
    // --resume leaves no mesh and replaces none.
    std::vector<geometry::MeshRectangle> rectangles;
    for (const auto& body : scene.bodies) {
        if (body.discretization == scene::Discretization::Fe) {
            rectangles.push_back({body.name, body.shape.boundZMin(), body.shape.boundZMax(),
                                  body.shape.boundRMin(), body.shape.boundRMax(), body.spacing});
        }
    }
    // SPH particles and FE elements; the particle slots FE elements erode into are not
    // particles until then.
    std::size_t sphParticles = 0;
    for (std::size_t i = 0; i < sim.particles().size(); ++i) {
        const auto body = static_cast<std::size_t>(sim.particles().body[i]);
        sphParticles += scene.bodies[body].discretization == scene::Discretization::Sph ? 1 : 0;
    }
    const std::size_t elements = sim.finiteElements() ? sim.finiteElements()->elements().size() : 0;
    info("scene '" + scene.id + "': " + std::to_string(sphParticles) + " SPH particles, " +
         std::to_string(elements) + " FE elements, " + std::to_string(scene.bodies.size()) +
         " bodies, spacing " + std::to_string(scene.sph.particleSpacing) + " mm, " +
         std::to_string(threads) + " threads, to " + std::to_string(scene.run.endTime) + " us");

    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::signal(SIGHUP, onSignal); // a closed terminal: stop as for SIGINT, with a checkpoint
    solver::RunOptions options;
    options.runFile = output;
    options.threads = threads;
    options.quiet = quiet();
    options.checkpointEverySeconds = m_checkpointEvery;
    options.resume = m_resume;
    const auto summary =
        solver::runToCompletion(sim, io::jsonText(scene.resolved), io::jsonText(materials), prov,
                                options, [this](const std::string& line) { info(line); });
    // Throughput of what the scene holds: particle-steps, element-steps, or both.
    const double wall = std::max(summary.wallSeconds, 1e-9);
    std::string rates;
    char buf[96];
    if (sphParticles > 0) {
        // Over the particles the steps evaluated too (the dormant ones and, with time-step
        // bins, those in the course of an interval are not).
        std::snprintf(buf, sizeof buf, "%.3e particle-steps/s (%.0f %% evaluated)",
                      summary.particleSteps / wall,
                      100.0 * summary.activeParticleSteps / std::max(summary.particleSteps, 1.0));
        rates = buf;
    }
    if (elements > 0) {
        std::snprintf(buf, sizeof buf, "%.3e element-steps/s", summary.elementSteps / wall);
        rates += (rates.empty() ? "" : ", ") + std::string(buf);
    }
    std::snprintf(buf, sizeof buf, "%.1f s", summary.wallSeconds);
    std::string wallText = buf;
    if (summary.resumed) { // the steps and rates are this part's; the whole run took more
        const double whole = summary.wholeWallSeconds();
        if (std::isfinite(whole)) {
            std::snprintf(buf, sizeof buf, " (%.1f s with the earlier parts)", whole);
            wallText += buf;
        } else {
            wallText += " (the earlier parts' time not recorded)";
        }
    }
    char line[640];
    std::snprintf(line, sizeof line,
                  "%s at t = %.4f us after %ld steps; wall %s; %s; max |energy error| "
                  "%.2e; wrote %s",
                  summary.stopReason.c_str(), summary.timeUs, summary.steps, wallText.c_str(),
                  rates.c_str(), summary.maxEnergyError, output.c_str());
    info(line);
    std::istringstream profile(solver::profileText(summary.profile));
    for (std::string row; std::getline(profile, row);) {
        info(row);
    }
    if (const fe::FeSolid* fe = sim.finiteElements(); fe && !rectangles.empty()) {
        const auto meshPath = std::filesystem::path(output).replace_extension(".msh");
        geometry::GmshMesher::write(rectangles, meshPath);
        info("FE mesh: " + std::to_string(fe->nodes().size()) + " nodes, " +
             std::to_string(fe->elements().size()) + " elements; written to " + meshPath.string());
    }
    if (!summary.complete) {
        throw Interrupted("run interrupted; resume with --resume");
    }
}

} // namespace hvi::app
