#include "solver/FePackage.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "io/CheckpointFields.hpp"

#include <cmath>

namespace hvi::solver {

FePackage::FePackage(const fe::FeOptions& options, FeAssembly assembly, ParticleState& points,
                     const material::MaterialPackage& particles)
    : m_axisymmetric(options.axisymmetric),
      m_solid(options, std::move(assembly.nodes), std::move(assembly.elements),
              std::move(assembly.erosionFactors)),
      m_materials(std::move(assembly.materials)), m_eroded(std::move(assembly.eroded)),
      m_points(points) {
    for (const auto& body : particles.bodies()) {
        m_rhoMin.push_back(0.1 * body.minDensity); // the particles' own clamp (SphPackage)
        m_rhoMax.push_back(body.maxDensity);
    }
}

void FePackage::drift(double dt) {
    auto& nd = m_solid.nodes();
    const bool axi = m_axisymmetric;
    const std::size_t n = nd.size();
#pragma omp parallel for schedule(static) if (n > kParallelMinItems)
    for (std::size_t k = 0; k < n; ++k) {
        if (!nd.alive[k]) {
            continue;
        }
        nd.z[k] += dt * nd.vz[k];
        nd.r[k] += dt * nd.vr[k];
        if (axi && nd.r[k] < 0.0) {
            nd.r[k] = -nd.r[k]; // reflect, as particles: no node ever has r < 0
            nd.vr[k] = std::fabs(nd.vr[k]);
        }
    }
}

void FePackage::kickNodes(double dt) {
    auto& nd = m_solid.nodes();
    const double half = 0.5 * dt;
    const bool axi = m_axisymmetric;
    // Only nodes with a force change: those of the last assembly (all after a resume).
    const std::vector<int32_t>* forced = m_solid.forcedNodes();
    const std::size_t n = forced ? forced->size() : nd.size();
#pragma omp parallel for schedule(static) if (n > kParallelMinItems)
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t k = forced ? static_cast<std::size_t>((*forced)[j]) : j;
        if (!nd.alive[k]) {
            continue;
        }
        const double inv = 1.0 / nd.mass[k];
        nd.vz[k] += half * nd.fz[k] * inv;
        nd.vr[k] += half * nd.fr[k] * inv;
        if (axi && nd.onAxis[k]) {
            nd.vr[k] = 0.0;
        }
    }
}

void FePackage::kickAgain(double dt) {
    kickNodes(dt);
    if (m_eroded) {
        convertErodedElements();
    }
}

void FePackage::convertErodedElements() {
    const auto& eroded = m_solid.erodedThisUpdate();
    if (eroded.empty()) {
        return;
    }
    const Stopwatch watch;
    const std::vector<int32_t> created = m_eroded->convert(
        eroded, m_solid.elements(), m_solid.nodes(), m_points.set, m_rhoMin, m_rhoMax);
    // A new particle starts the next step from its state (its rates are zero until the next
    // evaluation), so its half-step arrays are its state, as for any particle at rest.
    const HalfStep::Lanes lanes = m_points.lanes();
    for (const int32_t k : created) {
        lanes.hold(static_cast<std::size_t>(k));
    }
    m_points.aliveCount += created.size();
    m_points.evolving.include(created);
    bookSection("eroded elements to particles", watch.seconds());
}

void FePackage::prepare(double /*dtGuess*/) {
    m_solid.computeForces(m_materials);
}

void FePackage::save(io::CheckpointState& s) const {
    const auto& nd = m_solid.nodes();
    const auto& el = m_solid.elements();
    io::putFields(s, "node_", nd, fe::kNodeStateFields);
    io::putFlags(s, "node_alive", nd.alive);
    io::putFields(s, "element_", el, fe::kElementStateFields);
    s.doubles["element_volumetric_rate"] = m_solid.volumetricRate();
    s.doubles["element_hourglass_rate"] = m_solid.hourglassRate();
    io::putFlags(s, "element_alive", el.alive);
    if (el.hasStrength()) {
        io::putFields(s, "element_", el, fe::kElementStrengthFields);
    }
    s.extra["node_count"] = nd.size();
    s.extra["element_count"] = el.size();
    s.extra["eroded_energy_J"] = m_solid.erodedEnergy();
    s.extra["eroded_elements"] = m_solid.erodedCount();
    s.extra["fe_dt_us"] = m_solid.stableTimeStep();
    s.extra["fe_dt_element"] = m_solid.limitingElement();
}

void FePackage::restore(const io::CheckpointState& s) {
    auto& nd = m_solid.nodes();
    auto& el = m_solid.elements();
    if (s.extra.value("node_count", std::size_t{0}) != nd.size() ||
        s.extra.value("element_count", std::size_t{0}) != el.size()) {
        throw InputError("<checkpoint>", "/node_count",
                         "the checkpoint's FE mesh differs from the scene's",
                         "a checkpoint of the same scene and resolution");
    }
    io::takeFields(s, "node_", nd, fe::kNodeStateFields);
    io::takeFlags(s, "node_alive", nd.alive);
    io::takeFields(s, "element_", el, fe::kElementStateFields);
    io::takeArray(s, "element_volumetric_rate", m_solid.volumetricRate());
    io::takeArray(s, "element_hourglass_rate", m_solid.hourglassRate());
    io::takeFlags(s, "element_alive", el.alive);
    if (el.hasStrength()) {
        io::takeFields(s, "element_", el, fe::kElementStrengthFields);
    }
    m_solid.restoreErosion(s.extra.value("eroded_energy_J", 0.0),
                           s.extra.value("eroded_elements", std::size_t{0}));
    m_solid.recountNodeElements();
    m_materials.updatePressure(el);
    m_solid.restoreStableTimeStep(io::timeStepOf(s, "fe_dt_us"),
                                  s.extra.at("fe_dt_element").get<int32_t>());
}

} // namespace hvi::solver
