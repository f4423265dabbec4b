#include "solver/Simulation.hpp"
#include "core/Parallel.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hvi::solver {

namespace {
constexpr double kAxisClearance = 0.1; ///< particles are kept at r >= 0.1 h (Spheral's eta_min)
constexpr double kMaxDtGrowth = 1.25;
constexpr int kProgressEvery = 10; ///< steps between penetration checks
} // namespace

Simulation::Simulation(const scene::Scene& sceneIn, const material::MaterialLibrary& library,
                       SimulationOptions options)
    : m_scene(sceneIn), m_options(options) {
    const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;
    std::vector<InputIssue> issues;
    m_specs.reserve(m_scene.bodies.size());
    bool anyStrength = false;
    for (std::size_t b = 0; b < m_scene.bodies.size(); ++b) {
        const auto& body = m_scene.bodies[b];
        if (body.discretization == scene::Discretization::Fe) {
            issues.push_back({"<scene>", "/bodies/" + std::to_string(b) + "/discretization",
                              "finite-element bodies are not available in this version of "
                              "hvi-run",
                              "\"sph\" (foam2layers/hcomb2rings: --core-discretization sph)"});
            continue;
        }
        m_specs.push_back(library.get(body.material));
        anyStrength = anyStrength || (body.strength && m_specs.back().hasStrength());
    }
    if (!issues.empty()) {
        throw InputError(std::move(issues));
    }
    std::vector<BodyMaterial> bodyMaterials;
    m_minSpacing = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < m_scene.bodies.size(); ++b) {
        const auto& body = m_scene.bodies[b];
        const auto& spec = m_specs[b];
        const double rho0 = spec.referenceDensity;
        m_fills.push_back(sph::fillBody(body, static_cast<int32_t>(b), rho0, 0.0,
                                        m_scene.sph.smoothingLengthFactor, axi, m_particles));
        BodyMaterial bm;
        bm.spec = &m_specs[b];
        bm.strength = body.strength && spec.hasStrength();
        bm.minDensity = m_scene.sph.minDensityRatio * rho0;
        bm.first = m_fills.back().first;
        bm.count = m_fills.back().count;
        bodyMaterials.push_back(bm);
        m_minSpacing = std::min(m_minSpacing, m_fills.back().spacing);
    }
    // Strength arrays for every particle of every body (ParticleSet keeps an explicit flag,
    // so the order relative to the fill does not matter).
    if (anyStrength) {
        m_particles.enableStrength();
    }
    m_materials = std::make_unique<MaterialPackage>(std::move(bodyMaterials));

    sph::HydroOptions hydro;
    hydro.axisymmetric = axi;
    hydro.kernel = sph::kernelTypeFromName(m_scene.sph.kernel);
    hydro.avAlpha = m_scene.sph.avAlpha;
    hydro.avBeta = m_scene.sph.avBeta;
    m_hydro = std::make_unique<sph::SphHydro>(hydro);
    m_searchOptions.axisymmetric = axi;
    m_searchOptions.kernelSupport = sph::kKernelSupport;
    m_searchOptions.skipDormant = m_options.skipDormant;

    // Deletion limits: runaway speed and the domain box.
    const double vMax = m_scene.maxInitialSpeed();
    m_runawaySpeed = vMax > 0.0 ? m_scene.sph.runawaySpeedFactor * vMax
                                : std::numeric_limits<double>::infinity();
    double zLo = std::numeric_limits<double>::infinity(), zHi = -zLo, projectileSize = 0.0;
    for (const auto& body : m_scene.bodies) {
        zLo = std::min(zLo, body.shape.boundZMin());
        zHi = std::max(zHi, body.shape.boundZMax());
        projectileSize = std::max(projectileSize, body.shape.boundZMax() - body.shape.boundZMin());
    }
    m_zMin = m_scene.domain.zMin.value_or(zLo - 2.0 * projectileSize);
    m_zMax = m_scene.domain.zMax.value_or(zHi + 5.0);
    m_rMax = m_scene.domain.radius;
    m_penetrated.assign(m_scene.bodies.size(), 0);

    m_rates.resize(m_particles.size(), m_particles.hasStrength());
    m_aliveCount = m_particles.size();
    refreshRates();
    const Totals t = totals();
    m_initialEnergy = t.kinetic + t.internal;
    updateProgress();
}

void Simulation::refreshRates() {
    m_rates.resize(m_particles.size(), m_particles.hasStrength());
    m_materials->updatePressure(m_particles);
    computeRates();
}

void Simulation::computeRates() {
    sph::updateNeighbourList(m_particles, m_searchOptions, m_neighbours);
    m_rates.zero();
    m_hydro->evaluate(m_particles, m_neighbours, m_rates);
    m_materials->addStressRates(m_particles, m_neighbours.active, m_rates);
}

void Simulation::advance() {
    auto& ps = m_particles;
    const std::size_t n = ps.size();
    const bool strength = ps.hasStrength();
    const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;

    double dt = m_scene.run.cfl * m_hydro->stableTimeStep();
    if (!std::isfinite(dt)) {
        dt = m_scene.run.cfl * m_minSpacing; // nothing active: any step is stable
    }
    if (m_dt > 0.0) {
        dt = std::min(dt, kMaxDtGrowth * m_dt);
    }
    const double remaining = m_scene.run.endTime - m_time;
    if (remaining > 0.0 && dt > remaining) {
        dt = remaining;
    }
    const double half = 0.5 * dt;

    m_vzHalf.resize(n);
    m_vrHalf.resize(n);
    m_eHalf.resize(n);
    m_rhoHalf.resize(n);
    m_hHalf.resize(n);
    if (strength) {
        m_szzHalf.resize(n);
        m_srrHalf.resize(n);
        m_srzHalf.resize(n);
    }
    auto& rt = m_rates;
    // Half kick with the rates of the start of the step, drift, predict the end state.
#pragma omp parallel for schedule(static) if (n > kParallelMinItems)
    for (std::size_t i = 0; i < n; ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        m_vzHalf[i] = ps.vz[i] + half * rt.az[i];
        m_vrHalf[i] = ps.vr[i] + half * rt.ar[i];
        m_eHalf[i] = ps.e[i] + half * rt.de[i];
        m_rhoHalf[i] = ps.rho[i] + half * rt.drho[i];
        m_hHalf[i] = ps.h[i] + half * rt.dh[i];
        ps.z[i] += dt * m_vzHalf[i];
        ps.r[i] += dt * m_vrHalf[i];
        if (axi) {
            // Reflect at the axis: no particle ever has r < 0 (Spheral's AxisBoundaryRZ).
            const double rMin = kAxisClearance * ps.h[i];
            if (ps.r[i] < rMin) {
                ps.r[i] = std::max(2.0 * rMin - ps.r[i], rMin);
                m_vrHalf[i] = std::fabs(m_vrHalf[i]);
            }
        }
        ps.vz[i] = m_vzHalf[i] + half * rt.az[i];
        ps.vr[i] = m_vrHalf[i] + half * rt.ar[i];
        ps.e[i] = m_eHalf[i] + half * rt.de[i];
        ps.rho[i] = m_rhoHalf[i] + half * rt.drho[i];
        ps.h[i] = m_hHalf[i] + half * rt.dh[i];
        if (strength) {
            m_szzHalf[i] = ps.szz[i] + half * rt.dszz[i];
            m_srrHalf[i] = ps.srr[i] + half * rt.dsrr[i];
            m_srzHalf[i] = ps.srz[i] + half * rt.dsrz[i];
            ps.szz[i] = m_szzHalf[i] + half * rt.dszz[i];
            ps.srr[i] = m_srrHalf[i] + half * rt.dsrr[i];
            ps.srz[i] = m_srzHalf[i] + half * rt.dsrz[i];
        }
    }
    clampSmoothingLengths();
    m_materials->updatePressure(ps);
    computeRates();

    // Second half kick with the rates of the predicted end state.
    const auto& bodies = m_materials->bodies();
#pragma omp parallel for schedule(static) if (n > kParallelMinItems)
    for (std::size_t i = 0; i < n; ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        ps.vz[i] = m_vzHalf[i] + half * rt.az[i];
        ps.vr[i] = m_vrHalf[i] + half * rt.ar[i];
        ps.e[i] = m_eHalf[i] + half * rt.de[i];
        // Density and smoothing length stay within sane bounds: an expanding fragment's
        // density falls under the stress cut-off long before it nears zero.
        const double rhoFloor = 0.1 * bodies[static_cast<std::size_t>(ps.body[i])].minDensity;
        ps.rho[i] = std::max(m_rhoHalf[i] + half * rt.drho[i], rhoFloor);
        ps.h[i] = m_hHalf[i] + half * rt.dh[i];
        if (strength) {
            ps.szz[i] = m_szzHalf[i] + half * rt.dszz[i];
            ps.srr[i] = m_srrHalf[i] + half * rt.dsrr[i];
            ps.srz[i] = m_srzHalf[i] + half * rt.dsrz[i];
        }
    }
    clampSmoothingLengths();
    m_materials->applyPlasticity(ps, rt, m_neighbours.active);
    m_materials->updatePressure(ps);

    m_time += dt;
    m_dt = dt;
    ++m_step;
    deleteParticles();
    if (m_step % kProgressEvery == 0) {
        updateProgress();
    }
}

void Simulation::clampSmoothingLengths() {
    // Between a quarter and twice the initial value: the lower bound keeps h (and with it the
    // time step) from collapsing where particles pile up, the upper bound keeps the cells of
    // the neighbour search from growing with an expanding debris cloud.
    auto& ps = m_particles;
    for (const auto& fill : m_fills) {
        const double h0 = m_scene.sph.smoothingLengthFactor * fill.spacing;
        for (std::size_t i = fill.first; i < fill.first + fill.count; ++i) {
            ps.h[i] = std::clamp(ps.h[i], 0.25 * h0, 2.0 * h0);
        }
    }
}

void Simulation::deleteParticles() {
    auto& ps = m_particles;
    const std::size_t n = ps.size();
    const double runaway2 = m_runawaySpeed * m_runawaySpeed;
    for (std::size_t i = 0; i < n; ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        const double v2 = ps.vz[i] * ps.vz[i] + ps.vr[i] * ps.vr[i];
        if (!std::isfinite(v2) || !std::isfinite(ps.e[i]) || !std::isfinite(ps.rho[i]) ||
            !std::isfinite(ps.z[i]) || !std::isfinite(ps.r[i])) {
            throw RuntimeFailure(
                "non-finite state at t = " + std::to_string(m_time) + " us, step " +
                std::to_string(m_step) + ", particle " + std::to_string(i) + " of body '" +
                m_scene.bodies[static_cast<std::size_t>(ps.body[i])].name +
                "' (try a smaller cfl or a larger min_density_ratio)");
        }
        const bool runaway = v2 > runaway2;
        const bool outside = ps.z[i] < m_zMin || ps.z[i] > m_zMax || std::fabs(ps.r[i]) > m_rMax;
        if (runaway || outside) {
            ps.alive[i] = 0;
            m_deletedEnergy += ps.mass[i] * (0.5 * v2 + ps.e[i]);
            m_deletedMass += ps.mass[i];
            m_deletedMomentumZ += ps.mass[i] * ps.vz[i];
            ++(runaway ? m_runawayDeleted : m_outOfDomainDeleted);
            --m_aliveCount;
        }
    }
}

Totals Simulation::totals() const {
    const auto& ps = m_particles;
    Totals t;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i]) {
            ++t.deleted;
            continue;
        }
        ++t.alive;
        const double m = ps.mass[i];
        t.kinetic += 0.5 * m * (ps.vz[i] * ps.vz[i] + ps.vr[i] * ps.vr[i]);
        t.internal += m * ps.e[i];
        t.mass += m;
        t.momentumZ += m * ps.vz[i];
    }
    t.deletedEnergy = m_deletedEnergy;
    t.deletedMass = m_deletedMass;
    t.deletedMomentumZ = m_deletedMomentumZ;
    t.active = m_neighbours.active.size();
    return t;
}

double Simulation::energyError() const {
    const Totals t = totals();
    const double scale = std::fabs(m_initialEnergy) > 0.0 ? std::fabs(m_initialEnergy) : 1.0;
    return (t.kinetic + t.internal + t.deletedEnergy - m_initialEnergy) / scale;
}

void Simulation::updateProgress() {
    const auto& ps = m_particles;
    const double moving = m_scene.run.stopDebrisSpeed;
    double front = -std::numeric_limits<double>::infinity();
    double fastest = 0.0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        fastest = std::max(fastest, ps.vz[i]);
        if (ps.vz[i] > moving) {
            front = std::max(front, ps.z[i]);
        }
    }
    m_debrisSpeed = fastest;
    bool newPenetration = false;
    for (std::size_t b = 0; b < m_scene.bodies.size(); ++b) {
        const auto& body = m_scene.bodies[b];
        if (m_penetrated[b] || body.role == scene::BodyRole::Projectile) {
            continue;
        }
        const double rear = body.shape.boundZMax() + 0.5 * m_fills[b].spacing;
        const double rLo = body.shape.boundRMin(), rHi = body.shape.boundRMax();
        for (std::size_t i = 0; i < ps.size(); ++i) {
            if (ps.alive[i] && static_cast<std::size_t>(ps.body[i]) != b && ps.z[i] > rear &&
                ps.r[i] >= rLo && ps.r[i] <= rHi) {
                m_penetrated[b] = 1;
                newPenetration = true;
                break;
            }
        }
    }
    if (newPenetration || front > m_progressFront + m_minSpacing) {
        m_lastProgressTime = m_time;
        m_progressFront = std::max(front, m_progressFront);
    }
}

std::optional<std::string> Simulation::stopReason() const {
    const auto& run = m_scene.run;
    if (m_time >= run.endTime * (1.0 - 1e-12)) {
        return "end_time";
    }
    if (m_step >= run.maxSteps) {
        return "max_steps";
    }
    bool anyPenetrated = false;
    for (std::size_t b = 0; b < m_scene.bodies.size(); ++b) {
        anyPenetrated = anyPenetrated || m_penetrated[b];
        if (run.stopOnRearWallPerforation && m_penetrated[b] &&
            m_scene.bodies[b].role == scene::BodyRole::RearWall) {
            return "rear_wall_perforated";
        }
    }
    if (run.stopDebrisSpeed > 0.0 && m_step > 0 && m_debrisSpeed < run.stopDebrisSpeed) {
        return "debris_stopped";
    }
    if (run.stopNoNewPenetration > 0.0 && anyPenetrated &&
        m_time - m_lastProgressTime > run.stopNoNewPenetration) {
        return "no_new_penetration";
    }
    return std::nullopt;
}

void Simulation::restoreClock(double time, long step, double dt, double initialEnergy,
                              double deletedEnergy, double deletedMass, double deletedMomentumZ,
                              std::size_t runaway, std::size_t outOfDomain) {
    m_time = time;
    m_step = step;
    m_dt = dt;
    m_initialEnergy = initialEnergy;
    m_deletedEnergy = deletedEnergy;
    m_deletedMass = deletedMass;
    m_deletedMomentumZ = deletedMomentumZ;
    m_runawayDeleted = runaway;
    m_outOfDomainDeleted = outOfDomain;
    m_aliveCount = 0;
    for (const auto a : m_particles.alive) {
        m_aliveCount += a ? 1 : 0;
    }
    refreshRates();
    updateProgress();
}

} // namespace hvi::solver
