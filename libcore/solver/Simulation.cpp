#include "solver/Simulation.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

namespace hvi::solver {

namespace {
constexpr double kAxisClearance = 0.1; ///< particles are kept at r >= 0.1 h (Spheral's eta_min)
constexpr double kMaxDtGrowth = 1.25;
constexpr int kProgressEvery = 10;          ///< steps between penetration checks
constexpr std::size_t kFeCrossingItems = 3; ///< items behind an FE body's face: penetrated
} // namespace

Simulation::Simulation(const scene::Scene& sceneIn, const material::MaterialLibrary& library,
                       SimulationOptions options)
    : m_scene(sceneIn), m_options(options) {
    const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;
    m_specs.reserve(m_scene.bodies.size());
    bool anyStrength = false, anyFeStrength = false;
    for (const auto& body : m_scene.bodies) {
        m_specs.push_back(library.get(body.material));
        const bool strength = body.strength && m_specs.back().hasStrength();
        if (body.discretization == scene::Discretization::Fe) {
            anyFeStrength = anyFeStrength || strength;
            // Its eroded elements become particles that keep their stress state.
            anyStrength = anyStrength || (strength && m_scene.fe.erodedToParticles);
        } else {
            anyStrength = anyStrength || strength;
        }
    }
    if (m_scene.hasFeBodies() && m_scene.fe.erodedToParticles) {
        m_eroded = std::make_unique<ErodedParticles>(axi, m_scene.sph.smoothingLengthFactor);
    }
    std::vector<BodyMaterial> bodyMaterials, elementMaterials;
    std::vector<contact::ContactBody> contactBodies;
    std::vector<double> erosionFactors;
    fe::NodeSet nodes;
    fe::ElementSet elements;
    if (anyFeStrength) {
        elements.enableStrength();
    }
    m_minSpacing = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < m_scene.bodies.size(); ++b) {
        const auto& body = m_scene.bodies[b];
        const auto& spec = m_specs[b];
        const double rho0 = spec.referenceDensity;
        BodyMaterial bm;
        bm.spec = &m_specs[b];
        bm.strength = body.strength && spec.hasStrength();
        bm.minDensity = m_scene.sph.minDensityRatio * rho0;
        bm.maxDensity = densityCeiling(spec);
        BodyMaterial em = bm;
        if (body.discretization == scene::Discretization::Fe) {
            const fe::BodyMesh mesh =
                fe::meshBody(body, static_cast<int32_t>(b), rho0, 0.0, axi, nodes, elements);
            // The particles its eroded elements will become, held in reserve (or none).
            sph::BodyFill reserve;
            reserve.first = m_particles.size();
            reserve.spacing = mesh.elementSize;
            if (m_eroded) {
                m_eroded->reserve(mesh, static_cast<int32_t>(b), rho0, nodes, elements,
                                  m_particles);
                reserve.count = m_particles.size() - reserve.first;
            }
            m_fills.push_back(reserve);
            bm.first = reserve.first;
            bm.count = reserve.count;
            em.first = mesh.firstElement;
            em.count = mesh.elementCount;
            // Element density follows the swept volume exactly; the stress cut-off for an
            // expanded element is the same fraction as for a particle.
            contactBodies.push_back({true, mesh.elementSize});
        } else {
            m_fills.push_back(sph::fillBody(body, static_cast<int32_t>(b), rho0, 0.0,
                                            m_scene.sph.smoothingLengthFactor, axi, m_particles));
            bm.first = m_fills.back().first;
            bm.count = m_fills.back().count;
            contactBodies.push_back({false, m_fills.back().spacing});
        }
        if (body.discretization != scene::Discretization::Fe) {
            em.count = 0;
        }
        bodyMaterials.push_back(bm);
        elementMaterials.push_back(em);
        erosionFactors.push_back(body.erosionFactor);
        m_minSpacing = std::min(m_minSpacing, m_fills.back().spacing);
    }
    // Strength arrays for every particle of every body (ParticleSet keeps an explicit flag,
    // so the order relative to the fill does not matter).
    if (anyStrength) {
        m_particles.enableStrength();
    }
    m_materials = std::make_unique<MaterialPackage>(std::move(bodyMaterials));
    if (m_scene.hasFeBodies()) {
        m_feMaterials = std::make_unique<MaterialPackage>(std::move(elementMaterials));
        fe::FeOptions feOptions;
        feOptions.axisymmetric = axi;
        feOptions.hourglassCoefficient = m_scene.fe.hourglassCoefficient;
        feOptions.bulkLinear = m_scene.fe.bulkViscosityLinear;
        feOptions.bulkQuadratic = m_scene.fe.bulkViscosityQuadratic;
        feOptions.erodedBecomeParticles = m_eroded != nullptr;
        feOptions.skipDormant = m_options.skipDormant;
        feOptions.instantaneousErosionStrain = m_scene.fe.instantaneousErosionStrain;
        m_fe = std::make_unique<fe::FeSolid>(feOptions, std::move(nodes), std::move(elements),
                                             std::move(erosionFactors));
        contact::ContactOptions contactOptions;
        contactOptions.axisymmetric = axi;
        contactOptions.smoothingLengthFactor = m_scene.sph.smoothingLengthFactor;
        m_contact =
            std::make_unique<contact::KinematicContact>(contactOptions, std::move(contactBodies));
    }

    sph::HydroOptions hydro;
    hydro.axisymmetric = axi;
    hydro.kernel = sph::kernelTypeFromName(m_scene.sph.kernel);
    hydro.avAlpha = m_scene.sph.avAlpha;
    hydro.avBeta = m_scene.sph.avBeta;
    hydro.artificialStress = m_scene.sph.artificialStress;
    hydro.spacingOverH = 1.0 / m_scene.sph.smoothingLengthFactor;
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
    m_aliveCount = static_cast<std::size_t>(
        std::count(m_particles.alive.begin(), m_particles.alive.end(), uint8_t{1}));
    refreshRates();
    const Totals t = totals();
    m_initialEnergy = t.kinetic + t.internal;
    updateProgress();
}

void Simulation::restoreVotes(double sphDt, int32_t sphParticle, double feDt, int32_t feElement,
                              double contactDt, std::vector<uint8_t> contactFlags) {
    m_hydro->restoreStableTimeStep(sphDt, sphParticle);
    if (m_fe) {
        m_fe->restoreStableTimeStep(feDt, feElement);
        m_contact->restoreState(contactDt, std::move(contactFlags));
    }
}

void Simulation::refreshRates() {
    m_rates.resize(m_particles.size(), m_particles.hasStrength());
    m_rates.zero();
    m_materials->updatePressure(m_particles);
    resetHalfStep();
    computeRates();
    if (m_fe) {
        m_fe->computeForces(*m_feMaterials);
        // The contact time-step vote for the first step.
        double dt = m_dt;
        if (!(dt > 0.0)) {
            dt = m_scene.run.cfl * std::min(m_hydro->stableTimeStep(), m_fe->stableTimeStep());
        }
        m_contact->vote(m_particles, {&m_vzHalf, &m_vrHalf, &m_eHalf}, m_fe->elements(),
                        m_fe->nodes(), dt);
    }
}

void Simulation::driftNodes(double dt) {
    auto& nd = m_fe->nodes();
    const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;
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

void Simulation::kickNodes(double dt) {
    auto& nd = m_fe->nodes();
    const double half = 0.5 * dt;
    const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;
    // Only nodes with a force change: those of the last assembly (all after a resume).
    const std::vector<int32_t>* forced = m_fe->forcedNodes();
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

void Simulation::computeRates() {
    sph::updateNeighbourList(m_particles, m_searchOptions, m_neighbours);
    // Only particles that have evolved can hold non-zero rates: the evaluation writes the
    // rates of the active particles, and every active particle joins the evolving set.
    m_rates.zero(m_evolving);
    m_hydro->evaluate(m_particles, m_neighbours, m_rates, m_packAll ? nullptr : &m_evolving);
    m_packAll = false;
    m_materials->addStressRates(m_particles, m_neighbours.active, m_rates);
    includeEvolving(m_neighbours.active);
}

void Simulation::resetHalfStep() {
    const auto& ps = m_particles;
    m_vzHalf = ps.vz;
    m_vrHalf = ps.vr;
    m_eHalf = ps.e;
    m_rhoHalf = ps.rho;
    m_hHalf = ps.h;
    if (ps.hasStrength()) {
        m_szzHalf = ps.szz;
        m_srrHalf = ps.srr;
        m_srzHalf = ps.srz;
    }
    m_evolving.clear();
    m_isEvolving.assign(ps.size(), 0);
    m_packAll = true; // the particle arrays may have been replaced (a resume)
}

void Simulation::includeEvolving(const std::vector<int32_t>& items) {
    const std::size_t before = m_evolving.size();
    for (const int32_t i : items) {
        auto& flag = m_isEvolving[static_cast<std::size_t>(i)];
        if (!flag) {
            flag = 1;
            m_evolving.push_back(i);
        }
    }
    if (m_evolving.size() != before) {
        const auto mid = m_evolving.begin() + static_cast<std::ptrdiff_t>(before);
        std::sort(mid, m_evolving.end());
        std::inplace_merge(m_evolving.begin(), mid, m_evolving.end());
    }
}

void Simulation::advance() {
    auto& ps = m_particles;
    const bool strength = ps.hasStrength();
    const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;

    double vote = m_hydro->stableTimeStep();
    m_dtLimiter = "sph";
    if (m_fe) {
        if (m_fe->stableTimeStep() < vote) {
            vote = m_fe->stableTimeStep();
            m_dtLimiter = "fe";
        }
        if (m_contact->stableTimeStep() < vote) {
            vote = m_contact->stableTimeStep();
            m_dtLimiter = "contact";
        }
    }
    double dt = m_scene.run.cfl * vote;
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

    // The kick-drift-kick loops run over the evolving particles only (see includeEvolving):
    // every other particle is at rest in its reference state with zero rates, where a kick
    // or a drift changes nothing, and its half-step arrays already equal its state.
    const std::vector<int32_t>& evolving = m_evolving;
    auto& rt = m_rates;
    // Each package's share of the step (the benchmark's like-for-like figures): SPH is every
    // particle loop, FE the node integration, element update and eroded-element conversion,
    // contact the constraint alone.
    using Clock = std::chrono::steady_clock;
    auto lap = Clock::now();
    auto book = [&lap](double& seconds) {
        const auto now = Clock::now();
        seconds += std::chrono::duration<double>(now - lap).count();
        lap = now;
    };
    // Half kick with the rates of the start of the step.
    std::size_t count = evolving.size();
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
    for (std::size_t a = 0; a < count; ++a) {
        const auto i = static_cast<std::size_t>(evolving[a]);
        if (!ps.alive[i]) {
            continue;
        }
        m_vzHalf[i] = ps.vz[i] + half * rt.az[i];
        m_vrHalf[i] = ps.vr[i] + half * rt.ar[i];
        m_eHalf[i] = ps.e[i] + half * rt.de[i];
        m_rhoHalf[i] = ps.rho[i] + half * rt.drho[i];
        m_hHalf[i] = ps.h[i] + half * rt.dh[i];
        if (strength) {
            m_szzHalf[i] = ps.szz[i] + half * rt.dszz[i];
            m_srrHalf[i] = ps.srr[i] + half * rt.dsrr[i];
            m_srzHalf[i] = ps.srz[i] + half * rt.dsrz[i];
        }
    }
    book(m_packageSeconds.sph);
    if (m_fe) {
        kickNodes(dt);
        book(m_packageSeconds.fe);
        // Contact constrains the half-step velocities before anything drifts.
        m_contact->resolve(ps, {&m_vzHalf, &m_vrHalf, &m_eHalf}, m_fe->elements(), m_fe->nodes(),
                           dt);
        book(m_packageSeconds.contact);
        driftNodes(dt);
        book(m_packageSeconds.fe);
        // A dormant particle set moving by contact evolves from now on (its half-step state
        // equals its state, so the drift below is all it misses).
        includeEvolving(m_contact->touchedParticles());
        count = evolving.size();
    }
    // Drift, and predict the end state with the same rates.
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
    for (std::size_t a = 0; a < count; ++a) {
        const auto i = static_cast<std::size_t>(evolving[a]);
        if (!ps.alive[i]) {
            continue;
        }
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
            ps.szz[i] = m_szzHalf[i] + half * rt.dszz[i];
            ps.srr[i] = m_srrHalf[i] + half * rt.dsrr[i];
            ps.srz[i] = m_srzHalf[i] + half * rt.dsrz[i];
        }
    }
    clampSmoothingLengths();
    m_materials->updatePressure(ps, evolving);
    computeRates(); // the particles it activates join the evolving set
    count = evolving.size();
    book(m_packageSeconds.sph);
    if (m_fe) {
        m_fe->update(dt, *m_feMaterials);
        book(m_packageSeconds.fe);
    }

    // Second half kick with the rates of the predicted end state.
    const auto& bodies = m_materials->bodies();
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
    for (std::size_t a = 0; a < count; ++a) {
        const auto i = static_cast<std::size_t>(evolving[a]);
        if (!ps.alive[i]) {
            continue;
        }
        ps.vz[i] = m_vzHalf[i] + half * rt.az[i];
        ps.vr[i] = m_vrHalf[i] + half * rt.ar[i];
        ps.e[i] = m_eHalf[i] + half * rt.de[i];
        // Density and smoothing length stay within sane bounds: an expanding fragment's
        // density falls under the stress cut-off long before it nears zero, and no particle
        // is compressed beyond its equation of state's range (densityCeiling()).
        const auto& body = bodies[static_cast<std::size_t>(ps.body[i])];
        ps.rho[i] =
            std::clamp(m_rhoHalf[i] + half * rt.drho[i], 0.1 * body.minDensity, body.maxDensity);
        ps.h[i] = m_hHalf[i] + half * rt.dh[i];
        if (strength) {
            ps.szz[i] = m_szzHalf[i] + half * rt.dszz[i];
            ps.srr[i] = m_srrHalf[i] + half * rt.dsrr[i];
            ps.srz[i] = m_srzHalf[i] + half * rt.dsrz[i];
        }
    }
    book(m_packageSeconds.sph);
    if (m_fe) {
        kickNodes(dt);
        if (m_eroded) {
            convertErodedElements();
        }
        book(m_packageSeconds.fe);
    }
    clampSmoothingLengths();
    m_materials->applyPlasticity(ps, rt, m_neighbours.active, dt);
    m_materials->updatePressure(ps, evolving);

    m_time += dt;
    m_dt = dt;
    ++m_step;
    deleteParticles();
    book(m_packageSeconds.sph);
    if (m_step % kProgressEvery == 0) {
        updateProgress();
    }
}

void Simulation::convertErodedElements() {
    const auto& eroded = m_fe->erodedThisUpdate();
    if (eroded.empty()) {
        return;
    }
    const auto& bodies = m_materials->bodies();
    std::vector<double> rhoMin, rhoMax;
    for (const auto& body : bodies) {
        rhoMin.push_back(0.1 * body.minDensity); // the particles' own clamp (advance())
        rhoMax.push_back(body.maxDensity);
    }
    auto& ps = m_particles;
    const std::vector<int32_t> created =
        m_eroded->convert(eroded, m_fe->elements(), m_fe->nodes(), ps, rhoMin, rhoMax);
    // A new particle starts the next step from its state (its rates are zero until the next
    // evaluation), so its half-step arrays are its state, as for any particle at rest.
    for (const int32_t k : created) {
        const auto i = static_cast<std::size_t>(k);
        m_vzHalf[i] = ps.vz[i];
        m_vrHalf[i] = ps.vr[i];
        m_eHalf[i] = ps.e[i];
        m_rhoHalf[i] = ps.rho[i];
        m_hHalf[i] = ps.h[i];
        if (ps.hasStrength()) {
            m_szzHalf[i] = ps.szz[i];
            m_srrHalf[i] = ps.srr[i];
            m_srzHalf[i] = ps.srz[i];
        }
    }
    m_aliveCount += created.size();
    includeEvolving(created);
}

void Simulation::clampSmoothingLengths() {
    // At most twice the initial value, which keeps the cells of the neighbour search from
    // growing with an expanding debris cloud; at least the smoothing length of the densest
    // state the equation of state allows (h ~ rho^-1/2 in the (z, r) plane: h0 sqrt(rho0 /
    // rho_max), 0.67 h0 for Al), and never under a quarter of h0. Without the first lower
    // bound, particles squeezed against an FE surface shrank h to the quarter while their
    // density stopped at the ceiling, and set a time step ten times below the others'.
    auto& ps = m_particles;
    const auto& bodies = m_materials->bodies();
    for (std::size_t b = 0; b < m_fills.size(); ++b) {
        const auto& fill = m_fills[b];
        if (fill.count == 0) {
            continue;
        }
        const double hRef = m_scene.sph.smoothingLengthFactor * fill.spacing;
        const double densest = std::sqrt(m_specs[b].referenceDensity / bodies[b].maxDensity);
        const double hLow = std::max(0.25, densest) * hRef, hHigh = 2.0 * hRef;
        // The fill's slice of the (sorted) evolving set: nothing else has moved.
        const auto lo = std::lower_bound(m_evolving.begin(), m_evolving.end(),
                                         static_cast<int32_t>(fill.first));
        const auto hi =
            std::lower_bound(lo, m_evolving.end(), static_cast<int32_t>(fill.first + fill.count));
        for (auto it = lo; it != hi; ++it) {
            const auto i = static_cast<std::size_t>(*it);
            ps.h[i] = std::clamp(ps.h[i], hLow, hHigh);
        }
    }
}

void Simulation::deleteParticles() {
    auto& ps = m_particles;
    const double runaway2 = m_runawaySpeed * m_runawaySpeed;
    // After the first step only evolving particles can have moved out of bounds.
    const std::size_t n = m_step <= 1 ? ps.size() : m_evolving.size();
    for (std::size_t a = 0; a < n; ++a) {
        const std::size_t i = m_step <= 1 ? a : static_cast<std::size_t>(m_evolving[a]);
        if (!ps.alive[i]) {
            continue;
        }
        const double v2 = ps.vz[i] * ps.vz[i] + ps.vr[i] * ps.vr[i];
        if (!std::isfinite(v2) || !std::isfinite(ps.e[i]) || !std::isfinite(ps.rho[i]) ||
            !std::isfinite(ps.z[i]) || !std::isfinite(ps.r[i])) {
            throw RuntimeFailure("non-finite state at t = " + std::to_string(m_time) +
                                 " us, step " + std::to_string(m_step) + ", particle " +
                                 std::to_string(i) + " of body '" +
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
    if (!m_fe) {
        return;
    }
    // Nodes: a non-finite state is a failure; a free node (no alive element left) obeys the
    // same runaway and domain rules as a particle.
    auto& nd = m_fe->nodes();
    for (std::size_t k = 0; k < nd.size(); ++k) {
        if (!nd.alive[k]) {
            continue;
        }
        const double v2 = nd.vz[k] * nd.vz[k] + nd.vr[k] * nd.vr[k];
        if (!std::isfinite(v2) || !std::isfinite(nd.z[k]) || !std::isfinite(nd.r[k])) {
            throw RuntimeFailure("non-finite state at t = " + std::to_string(m_time) +
                                 " us, step " + std::to_string(m_step) + ", node " +
                                 std::to_string(k) + " of body '" +
                                 m_scene.bodies[static_cast<std::size_t>(nd.body[k])].name +
                                 "' (try a smaller cfl or a larger fe.hourglass_coefficient)");
        }
        if (nd.elementCount[k] > 0) {
            continue;
        }
        const bool runaway = v2 > runaway2;
        const bool outside = nd.z[k] < m_zMin || nd.z[k] > m_zMax || std::fabs(nd.r[k]) > m_rMax;
        if (runaway || outside) {
            nd.alive[k] = 0;
            m_deletedEnergy += 0.5 * nd.mass[k] * v2;
            m_deletedMass += nd.mass[k];
            m_deletedMomentumZ += nd.mass[k] * nd.vz[k];
            ++(runaway ? m_runawayDeleted : m_outOfDomainDeleted);
        }
    }
}

Totals Simulation::totals() const {
    const auto& ps = m_particles;
    Totals t;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i]) {
            t.deleted += sph::isUnusedSlot(ps.alive[i], ps.mass[i]) ? 0 : 1;
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
    if (m_fe) {
        const auto& nd = m_fe->nodes();
        for (std::size_t k = 0; k < nd.size(); ++k) {
            if (nd.alive[k]) {
                const double m = nd.mass[k];
                t.kinetic += 0.5 * m * (nd.vz[k] * nd.vz[k] + nd.vr[k] * nd.vr[k]);
                t.mass += m;
                t.momentumZ += m * nd.vz[k];
            }
        }
        const auto& el = m_fe->elements();
        for (std::size_t i = 0; i < el.size(); ++i) {
            if (el.alive[i]) {
                t.internal += el.mass[i] * el.e[i];
            }
        }
        t.deletedEnergy += m_fe->erodedEnergy() + m_contact->freeNodeHeat();
        t.erodedElements = m_fe->erodedCount();
    }
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
    double fastest = 0.0;
    // Progress of the material moving forward (faster than the stop speed): its foremost
    // item, and its centre of mass. Either advancing by a spacing counts, so neither a lone
    // slow item stalled ahead of the cloud (against a layer) nor a few fast stray items hide
    // a debris cloud that is still crossing a gap.
    double front = -std::numeric_limits<double>::infinity();
    double movingMass = 0.0, movingMoment = 0.0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        fastest = std::max(fastest, ps.vz[i]);
        if (ps.vz[i] > moving) {
            front = std::max(front, ps.z[i]);
            movingMass += ps.mass[i];
            movingMoment += ps.mass[i] * ps.z[i];
        }
    }
    const fe::NodeSet* nodes = m_fe ? &m_fe->nodes() : nullptr;
    if (nodes) {
        for (std::size_t k = 0; k < nodes->size(); ++k) {
            if (!nodes->alive[k]) {
                continue;
            }
            fastest = std::max(fastest, nodes->vz[k]);
            if (nodes->vz[k] > moving) {
                front = std::max(front, nodes->z[k]);
                movingMass += nodes->mass[k];
                movingMoment += nodes->mass[k] * nodes->z[k];
            }
        }
    }
    m_debrisSpeed = fastest;
    const double centre =
        movingMass > 0.0 ? movingMoment / movingMass : -std::numeric_limits<double>::infinity();
    bool newPenetration = false;
    for (std::size_t b = 0; b < m_scene.bodies.size(); ++b) {
        const auto& body = m_scene.bodies[b];
        if (m_penetrated[b] || body.role == scene::BodyRole::Projectile) {
            continue;
        }
        const double spacing = m_fills[b].spacing;
        const double rear = body.shape.boundZMax() + 0.5 * spacing;
        const double rLo = body.shape.boundRMin(), rHi = body.shape.boundRMax();
        // An FE body bulges without breaking: it is penetrated where material of other
        // bodies lies behind its initial rear face in a radial bin (one element wide) that
        // holds none of its meshed material any more, a hole. SPH bodies: anything behind the
        // initial face (their own spall counts as debris).
        std::vector<double> rearOf;
        const bool fe = body.discretization == scene::Discretization::Fe;
        if (fe) {
            rearOf.assign(static_cast<std::size_t>((rHi - rLo) / spacing) + 2,
                          -std::numeric_limits<double>::infinity());
            for (std::size_t k = 0; k < nodes->size(); ++k) {
                if (static_cast<std::size_t>(nodes->body[k]) == b && nodes->elementCount[k] > 0) {
                    const double bin = std::floor((nodes->r[k] - rLo) / spacing);
                    if (bin >= 0.0 && bin < static_cast<double>(rearOf.size())) {
                        auto& slot = rearOf[static_cast<std::size_t>(bin)];
                        slot = std::max(slot, nodes->z[k] + 0.5 * spacing);
                    }
                }
            }
        }
        auto behind = [&](double z, double r) {
            if (r < rLo || r > rHi) {
                return false;
            }
            if (!fe) {
                return z > rear;
            }
            // Only where the body has no meshed material left (a hole) does material behind
            // the initial face count: where it still has some, the wall holds there, whatever
            // lone free node got past it.
            const auto bin = static_cast<std::size_t>((r - rLo) / spacing);
            return bin < rearOf.size() && !std::isfinite(rearOf[bin]) && z > rear;
        };
        // SPH bodies: one item behind the face. FE bodies: as many as hvi-assess asks for
        // material crossing a rear wall (assess::Criteria::minCrossingItems), so that a lone
        // free node slipping through a one-element crater on the axis ends no run early.
        const std::size_t needed = fe ? kFeCrossingItems : 1;
        std::size_t crossing = 0;
        for (std::size_t i = 0; i < ps.size() && crossing < needed; ++i) {
            if (ps.alive[i] && static_cast<std::size_t>(ps.body[i]) != b &&
                behind(ps.z[i], ps.r[i])) {
                ++crossing;
            }
        }
        for (std::size_t k = 0; nodes && crossing < needed && k < nodes->size(); ++k) {
            if (nodes->alive[k] && static_cast<std::size_t>(nodes->body[k]) != b &&
                behind(nodes->z[k], nodes->r[k])) {
                ++crossing;
            }
        }
        if (crossing >= needed) {
            m_penetrated[b] = 1;
            newPenetration = true;
        }
    }
    // Progress is an advance of at least what the stop speed carries material in the rule's
    // window (or a spacing, if less): a layer still bulging at the stop speed under the debris
    // pressing on it is progress. With a spacing alone (0.16 km/s for 0.04 mm in 0.25 us)
    // HITF03147-3 stopped at 8.9 us with the debris still pushing its rear facesheet at
    // 0.7 km/s, which tore at 12.2 us.
    const double window = m_scene.run.stopNoNewPenetration;
    const double advance =
        window > 0.0 && moving > 0.0 ? std::min(m_minSpacing, moving * window) : m_minSpacing;
    if (newPenetration || front > m_progressFront + advance ||
        centre > m_progressCentre + advance) {
        m_lastProgressTime = m_time;
        m_progressFront = std::max(front, m_progressFront);
        m_progressCentre = std::max(centre, m_progressCentre);
    }
    // The wall check is a pass over every point: made only once progress has stalled for
    // half the window (the clock advances after this call, so not the whole window).
    m_rearWallActive = false;
    if (window > 0.0 && m_time - m_lastProgressTime > 0.5 * window) {
        updateRearWallActivity(moving);
    }
}

void Simulation::updateRearWallActivity(double speed) {
    m_rearWallActive = false;
    double zRear = -std::numeric_limits<double>::infinity();
    double rLo = std::numeric_limits<double>::infinity(), rHi = -rLo;
    std::vector<uint8_t> isWall(m_scene.bodies.size(), 0);
    for (std::size_t b = 0; b < m_scene.bodies.size(); ++b) {
        const auto& body = m_scene.bodies[b];
        if (body.role == scene::BodyRole::RearWall) {
            isWall[b] = 1;
            zRear = std::max(zRear, body.shape.boundZMax() + 0.5 * m_fills[b].spacing);
            rLo = std::min(rLo, body.shape.boundRMin());
            rHi = std::max(rHi, body.shape.boundRMax());
        }
    }
    if (!std::isfinite(zRear) || speed <= 0.0) {
        return;
    }
    // The wall itself: its meshed nodes moving either way, or its particles moving outward
    // no further than a wall thickness behind its rear face (a bulge or spall leaving; spall
    // that has flown further, and ejecta thrown back off its front, which move away from
    // the wall for good, are no longer the wall). Other bodies: what is in front of its rear
    // face, within its radial extent, moving toward it.
    auto approaching = [&](std::int32_t body, double z, double r, double vz) {
        return !isWall[static_cast<std::size_t>(body)] && vz > speed && z < zRear && r >= rLo &&
               r <= rHi;
    };
    const auto& ps = m_particles;
    for (std::size_t i = 0; i < ps.size() && !m_rearWallActive; ++i) {
        if (!ps.alive[i]) {
            continue;
        }
        const auto b = static_cast<std::size_t>(ps.body[i]);
        const bool wallMoving = isWall[b] && ps.vz[i] > speed &&
                                ps.z[i] < zRear + m_scene.bodies[b].shape.boundZMax() -
                                              m_scene.bodies[b].shape.boundZMin();
        m_rearWallActive = wallMoving || approaching(ps.body[i], ps.z[i], ps.r[i], ps.vz[i]);
    }
    if (m_fe) {
        const fe::NodeSet& nodes = m_fe->nodes();
        for (std::size_t k = 0; k < nodes.size() && !m_rearWallActive; ++k) {
            if (!nodes.alive[k]) {
                continue;
            }
            const bool wallMoving = isWall[static_cast<std::size_t>(nodes.body[k])] &&
                                    nodes.elementCount[k] > 0 && std::fabs(nodes.vz[k]) > speed;
            m_rearWallActive =
                wallMoving || approaching(nodes.body[k], nodes.z[k], nodes.r[k], nodes.vz[k]);
        }
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
    // Not while material still moves toward or in the rear wall: the wall may yet fail.
    if (run.stopNoNewPenetration > 0.0 && anyPenetrated && !m_rearWallActive &&
        m_time - m_lastProgressTime > run.stopNoNewPenetration) {
        return "no_new_penetration";
    }
    return std::nullopt;
}

void Simulation::restoreClock(double time, long step, double dt, double initialEnergy,
                              double deletedEnergy, double deletedMass, double deletedMomentumZ,
                              std::size_t runaway, std::size_t outOfDomain, double erodedEnergy,
                              std::size_t erodedCount) {
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
    m_rates.resize(m_particles.size(), m_particles.hasStrength());
    m_materials->updatePressure(m_particles);
    // Which particles evolved before the checkpoint is not stored: all of them evolve from
    // here (exact, only slower by the dormant ones until the end of the run).
    resetHalfStep();
    m_evolving.resize(m_particles.size());
    std::iota(m_evolving.begin(), m_evolving.end(), 0);
    m_isEvolving.assign(m_particles.size(), 1);
    computeRates(); // the neighbour lists; the rates themselves come from the checkpoint
    if (m_fe) {
        m_fe->restoreErosion(erodedEnergy, erodedCount);
        m_fe->recountNodeElements();
        m_feMaterials->updatePressure(m_fe->elements());
    }
    updateProgress();
}

} // namespace hvi::solver
