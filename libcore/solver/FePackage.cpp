#include "solver/FePackage.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "io/CheckpointFields.hpp"

#include <cmath>

namespace hvi::solver {

FePackage::FePackage(const fe::FeOptions& options, FeAssembly assembly, ParticleState& points,
                     const material::MaterialPackage& particles, bool timeBins, double cfl)
    : m_axisymmetric(options.axisymmetric),
      m_solid(options, std::move(assembly.nodes), std::move(assembly.elements),
              std::move(assembly.erosionFactors)),
      m_materials(std::move(assembly.materials)), m_eroded(std::move(assembly.eroded)),
      m_points(points), m_binned(timeBins), m_cfl(cfl) {
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
    const std::vector<int32_t>* forced =
        m_binned ? m_solid.impulseNodes() : m_solid.forcedNodes();
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

void FePackage::kick(double dt) {
    if (m_binned) {
        openIntervals(dt);
    }
    kickNodes(dt);
}

void FePackage::evaluate(double dt) {
    if (m_binned) {
        closeIntervals(dt);
    } else {
        m_solid.update(dt, m_materials);
    }
}

void FePackage::finish(double dt) {
    if (m_binned) {
        m_bins.endStep(m_solid.evaluatedElements(), m_solid.elements().alive, dt);
    }
}

template <class WeightA, class WeightB>
void FePackage::mergeWeighted(std::span<const int32_t> a, WeightA&& weightA,
                              std::span<const int32_t> b, WeightB&& weightB) {
    m_list.clear();
    m_weight.clear();
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        const int32_t next = j == b.size() || (i < a.size() && a[i] <= b[j]) ? a[i] : b[j];
        double w = 0.0;
        if (i < a.size() && a[i] == next) {
            w += weightA(static_cast<std::size_t>(a[i++]));
        }
        if (j < b.size() && b[j] == next) {
            w += weightB(static_cast<std::size_t>(b[j++]));
        }
        m_list.push_back(next);
        m_weight.push_back(w);
    }
}

void FePackage::openIntervals(double dt) {
    const auto& el = m_solid.elements();
    const auto& nd = m_solid.nodes();
    m_bins.beginStep(m_solid.evaluatedElements(), el.alive, m_cfl, dt);
    const std::vector<int32_t>& opening = m_bins.opening();
    parallelFor(opening.size(), [&](std::size_t k) {
        const auto e = static_cast<std::size_t>(opening[k]);
        double* x0 = &m_intervalStart[8 * e];
        for (int a = 0; a < 4; ++a) {
            const auto n = static_cast<std::size_t>(el.node(e, a));
            x0[2 * a] = nd.z[n];
            x0[2 * a + 1] = nd.r[n];
        }
    });
    // Impulses in units of the half kick dt/2 f: half the planned interval for an opening
    // element, and the correction to half the actual one for a shortened one (its force of
    // the interval's start), so that each interval's two kicks total its length.
    const double half = 0.5 * dt;
    mergeWeighted(
        opening, [&](std::size_t e) { return m_bins.openingHalf(e) / half; }, m_bins.shortened(),
        [&](std::size_t e) { return m_bins.closingCorrection(e) / half; });
    m_solid.gatherImpulses(m_list, m_weight);
}

void FePackage::closeIntervals(double dt) {
    const std::span<const int32_t> woken = m_solid.wake();
    for (const int32_t e : woken) {
        m_bins.admit(static_cast<std::size_t>(e), dt);
    }
    const auto one = [](std::size_t) { return 1.0; };
    mergeWeighted(m_bins.closing(), one, woken, one);
    m_solid.updateElements(m_list, {&m_bins.intervals(), &m_intervalStart, dt}, m_materials);
    // Each evaluated element's vote, and its bin's bound on the elements that share a node
    // with it (the wake-up); then the second kick's weights, half the interval each.
    const auto& el = m_solid.elements();
    const auto& own = m_solid.ownSteps();
    const fe::NodeCorners& corners = m_solid.nodeCorners();
    const double cfl = m_cfl;
    parallelFor(m_list.size(), [&](std::size_t k) {
        const auto e = static_cast<std::size_t>(m_list[k]);
        m_weight[k] = m_bins.closingHalf(e) / (0.5 * dt);
        if (!el.alive[e]) {
            return;
        }
        m_bins.setVote(e, own[e]);
        const int level = TimeBins::levelFor(cfl, own[e], dt, TimeBins::kMaxLevel);
        if (level + TimeBins::kWakeLevels >= TimeBins::kMaxLevel) {
            return;
        }
        for (int a = 0; a < 4; ++a) {
            const auto n = static_cast<std::size_t>(el.node(e, a));
            for (int64_t c = corners.offset[n]; c < corners.offset[n + 1]; ++c) {
                const auto other = static_cast<std::size_t>(
                    fe::NodeCorners::elementOf(corners.corners[static_cast<std::size_t>(c)]));
                if (other != e) {
                    m_bins.wakeNeighbour(other, level);
                }
            }
        }
    });
}

void FePackage::wakeAtNodes(std::span<const int32_t> nodes) {
    if (!m_binned) {
        return;
    }
    const fe::NodeCorners& corners = m_solid.nodeCorners();
    for (const int32_t node : nodes) {
        const auto n = static_cast<std::size_t>(node);
        for (int64_t c = corners.offset[n]; c < corners.offset[n + 1]; ++c) {
            m_bins.limit(fe::NodeCorners::elementOf(corners.corners[static_cast<std::size_t>(c)]),
                         0);
        }
    }
}

void FePackage::kickAgain(double dt) {
    if (m_binned) {
        m_solid.gatherImpulses(m_list, m_weight);
    }
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
    if (m_binned) {
        m_bins.reset(m_solid.elements().size());
        m_intervalStart.assign(8 * m_solid.elements().size(), 0.0);
    }
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
    if (m_binned) {
        m_bins.save(s, "element_bins_");
        s.doubles["element_interval_start_mm"] = m_intervalStart;
        s.doubles["element_corner_force"] = m_solid.cornerForces();
        s.doubles["element_own_step_us"] = m_solid.ownSteps();
        s.doubles["element_volume_mm3"] = m_solid.volumes();
        // The pressure of an element's last evaluation: contact heat raises e in between,
        // and the next evaluation starts from that pressure, not the one of the raised e.
        s.doubles["element_pressure_GPa"] = el.p;
        s.doubles["element_sound_speed_km_s"] = el.cs;
        io::putFlags(s, "element_awake", m_solid.awakeFlags());
    }
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
    if (m_binned) {
        // The elements in the course of an interval hold the forces and votes of its start.
        m_bins.restore(s, "element_bins_");
        io::takeArray(s, "element_interval_start_mm", m_intervalStart);
        io::takeArray(s, "element_corner_force", m_solid.cornerForces());
        io::takeArray(s, "element_own_step_us", m_solid.ownSteps());
        io::takeArray(s, "element_volume_mm3", m_solid.volumes());
        io::takeArray(s, "element_pressure_GPa", el.p);
        io::takeArray(s, "element_sound_speed_km_s", el.cs);
        std::vector<uint8_t> awake(el.size(), 0);
        io::takeFlags(s, "element_awake", awake);
        m_solid.restoreAwake(awake);
    }
}

} // namespace hvi::solver
