#include "solver/Simulation.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

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
    std::vector<material::BodyMaterial> bodyMaterials, elementMaterials;
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
        material::BodyMaterial bm;
        bm.spec = &m_specs[b];
        bm.strength = body.strength && spec.hasStrength();
        bm.minDensity = m_scene.sph.minDensityRatio * rho0;
        bm.maxDensity = material::densityCeiling(spec);
        material::BodyMaterial em = bm;
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
    m_materials = std::make_unique<material::MaterialPackage>(std::move(bodyMaterials));
    if (m_scene.hasFeBodies()) {
        m_feMaterials = std::make_unique<material::MaterialPackage>(std::move(elementMaterials));
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

    m_deletion = DeletionRule::of(m_scene);
    std::vector<double> spacing;
    for (const auto& fill : m_fills) {
        spacing.push_back(fill.spacing);
    }
    m_stop = std::make_unique<StopRules>(m_scene, std::move(spacing));

    m_rates.resize(m_particles.size(), m_particles.hasStrength());
    m_aliveCount = static_cast<std::size_t>(
        std::count(m_particles.alive.begin(), m_particles.alive.end(), uint8_t{1}));
    refreshRates();
    const Totals t = totals();
    m_ledger.setInitialEnergy(t.kinetic + t.internal);
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
        m_contact->vote(m_particles, m_half.contactView(), m_fe->elements(), m_fe->nodes(), dt);
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
    m_half.reset(ps);
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

double Simulation::nextTimeStep() {
    // The packages' votes in a fixed order; a tie goes to the first.
    struct Vote {
        const char* package;
        double dt;
    };
    const double inf = std::numeric_limits<double>::infinity();
    const std::array<Vote, 3> votes{{
        {"sph", m_hydro->stableTimeStep()},
        {"fe", m_fe ? m_fe->stableTimeStep() : inf},
        {"contact", m_contact ? m_contact->stableTimeStep() : inf},
    }};
    const Vote* smallest = &votes[0];
    for (const Vote& v : votes) {
        if (v.dt < smallest->dt) {
            smallest = &v;
        }
    }
    m_dtLimiter = smallest->package;
    double dt = m_scene.run.cfl * smallest->dt;
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
    return dt;
}

void Simulation::advance() {
    auto& ps = m_particles;
    const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;
    const double dt = nextTimeStep();
    const double half = 0.5 * dt;

    // The kick-drift-kick loops run over the evolving particles only (see includeEvolving):
    // every other particle is at rest in its reference state with zero rates, where a kick
    // or a drift changes nothing, and its half-step arrays already equal its state.
    const std::vector<int32_t>& evolving = m_evolving;
    const HalfStep::Lanes lanes = m_half.lanes(ps, m_rates);
    const std::vector<double>& vzHalf = m_half.vz();
    std::vector<double>& vrHalf = m_half.vr();
    // Each package's share of the step (the benchmark's like-for-like figures): SPH is every
    // particle loop, FE the node integration, element update and eroded-element conversion,
    // contact the constraint alone.
    using WallClock = std::chrono::steady_clock;
    auto lap = WallClock::now();
    auto book = [&lap](double& seconds) {
        const auto now = WallClock::now();
        seconds += std::chrono::duration<double>(now - lap).count();
        lap = now;
    };
    // Half kick with the rates of the start of the step.
    std::size_t count = evolving.size();
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
    for (std::size_t a = 0; a < count; ++a) {
        const auto i = static_cast<std::size_t>(evolving[a]);
        if (ps.alive[i]) {
            lanes.kick(i, half);
        }
    }
    book(m_packageSeconds.sph);
    if (m_fe) {
        kickNodes(dt);
        book(m_packageSeconds.fe);
        // Contact constrains the half-step velocities before anything drifts.
        m_contact->resolve(ps, m_half.contactView(), m_fe->elements(), m_fe->nodes(), dt);
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
        ps.z[i] += dt * vzHalf[i];
        ps.r[i] += dt * vrHalf[i];
        if (axi) {
            // Reflect at the axis: no particle ever has r < 0 (Spheral's AxisBoundaryRZ).
            const double rMin = kAxisClearance * ps.h[i];
            if (ps.r[i] < rMin) {
                ps.r[i] = std::max(2.0 * rMin - ps.r[i], rMin);
                vrHalf[i] = std::fabs(vrHalf[i]);
            }
        }
        lanes.predict(i, half);
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
        lanes.predict(i, half);
        // Density stays within sane bounds: an expanding fragment's density falls under the
        // stress cut-off long before it nears zero, and no particle is compressed beyond its
        // equation of state's range (densityCeiling()).
        const auto& body = bodies[static_cast<std::size_t>(ps.body[i])];
        ps.rho[i] = std::clamp(ps.rho[i], 0.1 * body.minDensity, body.maxDensity);
    }
    book(m_packageSeconds.sph);
    if (m_fe) {
        kickNodes(dt);
        if (m_eroded) {
            convertErodedElements(lanes);
        }
        book(m_packageSeconds.fe);
    }
    clampSmoothingLengths();
    m_materials->applyPlasticity(ps, m_rates, m_neighbours.active, dt);
    m_materials->updatePressure(ps, evolving);

    m_time += dt;
    m_dt = dt;
    ++m_step;
    deletePoints();
    book(m_packageSeconds.sph);
    if (m_step % kProgressEvery == 0) {
        updateProgress();
    }
}

void Simulation::convertErodedElements(const HalfStep::Lanes& lanes) {
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
        lanes.hold(static_cast<std::size_t>(k));
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

void Simulation::deletePoints() {
    // After the first step only evolving particles can have moved out of bounds.
    const RunClock clock{m_time, m_step};
    m_aliveCount -= deleteParticles(m_particles, m_step <= 1 ? nullptr : &m_evolving, m_deletion,
                                    m_scene, clock, m_ledger);
    if (m_fe) {
        deleteFreeNodes(m_fe->nodes(), m_deletion, m_scene, clock, m_ledger);
    }
}

Totals Simulation::totals() const {
    return m_ledger.totals(m_particles, m_fe.get(), m_contact.get(), m_neighbours.active.size());
}

double Simulation::energyError() const {
    return m_ledger.energyError(totals());
}

void Simulation::updateProgress() {
    m_stop->update(m_time, m_particles, m_fe ? &m_fe->nodes() : nullptr);
}

void Simulation::restoreClock(const Clock& clock, const Ledger::Account& account,
                              const ErosionAccount& erosion) {
    m_time = clock.time;
    m_step = clock.step;
    m_dt = clock.dt;
    m_ledger.restore(account);
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
        m_fe->restoreErosion(erosion.energy, erosion.count);
        m_fe->recountNodeElements();
        m_feMaterials->updatePressure(m_fe->elements());
    }
    updateProgress();
}

} // namespace hvi::solver
