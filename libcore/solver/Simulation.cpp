#include "solver/Simulation.hpp"

#include "solver/SceneAssembly.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hvi::solver {

namespace {
constexpr int kProgressEvery = 10; ///< steps between penetration checks
/// Simulated time between two confirmations of a rear-wall perforation [us]: the assessment
/// costs a copy of the state and a pass over it, so it is asked at most this often.
constexpr double kRearWallCheckEveryUs = 0.5;
} // namespace

Simulation::Simulation(const scene::Scene& sceneIn, const material::MaterialLibrary& library,
                       SimulationOptions options)
    : m_scene(sceneIn) {
    SceneAssembly parts = assembleScene(m_scene, library);
    m_specs = std::move(parts.specs); // moved, not copied: the body materials point into it
    m_fills = std::move(parts.fills);
    m_minSpacing = parts.minSpacing;
    m_points.set = std::move(parts.particles);
    m_sph = std::make_unique<SphPackage>(m_scene, m_points, m_fills, m_specs,
                                         std::move(parts.particleMaterials), options.skipDormant);
    m_loop.add(*m_sph);
    if (m_scene.hasFeBodies()) {
        const bool axi = m_scene.geometry == scene::Geometry::Axisymmetric;
        fe::FeOptions feOptions;
        feOptions.axisymmetric = axi;
        feOptions.hourglassCoefficient = m_scene.fe.hourglassCoefficient;
        feOptions.bulkLinear = m_scene.fe.bulkViscosityLinear;
        feOptions.bulkQuadratic = m_scene.fe.bulkViscosityQuadratic;
        feOptions.erodedBecomeParticles = parts.fe.eroded != nullptr;
        feOptions.skipDormant = options.skipDormant;
        feOptions.instantaneousErosionStrain = m_scene.fe.instantaneousErosionStrain;
        std::vector<contact::ContactBody> contactBodies = std::move(parts.fe.contactBodies);
        m_fe = std::make_unique<FePackage>(feOptions, std::move(parts.fe), m_points,
                                           m_sph->materials(), m_scene.fe.timeBins,
                                           m_scene.run.cfl);
        contact::ContactOptions contactOptions;
        contactOptions.axisymmetric = axi;
        contactOptions.smoothingLengthFactor = m_scene.sph.smoothingLengthFactor;
        m_contact = std::make_unique<ContactPackage>(contactOptions, std::move(contactBodies),
                                                     m_points, *m_fe);
        m_loop.add(*m_fe);
        m_loop.add(*m_contact);
    }

    m_deletion = DeletionRule::of(m_scene);
    std::vector<double> spacing;
    for (const auto& fill : m_fills) {
        spacing.push_back(fill.spacing);
    }
    m_stop = std::make_unique<StopRules>(m_scene, std::move(spacing));
    if (m_scene.run.stopOnRearWallPerforation) {
        m_rearWall =
            std::make_unique<RearWallConfirmation>(m_scene, m_points.set, finiteElements());
    }

    m_points.countAlive();
    refreshRates();
    const Totals t = totals();
    m_ledger.setInitialEnergy(t.kinetic + t.internal);
    updateProgress();
}

void Simulation::resetTimes() {
    m_loop.resetTimes();
    m_deletionSeconds = 0.0;
    m_stopRuleSeconds = 0.0;
}

void Simulation::refreshRates() {
    m_loop.prepare(m_dt, m_scene.run.cfl);
}

Simulation::PackageSeconds Simulation::packageSeconds() const {
    return {m_sph->seconds() + m_deletionSeconds, m_fe ? m_fe->seconds() : 0.0,
            m_contact ? m_contact->seconds() : 0.0};
}

double Simulation::nextTimeStep() {
    const PackageLoop::Vote vote = m_loop.smallestVote();
    m_dtLimiter = vote.limiter->name();
    m_loop.countBinnedWork(vote.dt);
    double dt = m_scene.run.cfl * vote.dt;
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
    const double dt = nextTimeStep();
    m_loop.step(dt);
    m_time += dt;
    m_dt = dt;
    ++m_step;
    const Stopwatch deletion;
    deletePoints();
    m_deletionSeconds += deletion.seconds();
    if (m_step % kProgressEvery == 0) {
        const Stopwatch stopRules;
        updateProgress();
        m_stopRuleSeconds += stopRules.seconds();
    }
}

void Simulation::deletePoints() {
    // After the first step only evolving particles can have moved out of bounds.
    const RunClock clock{m_time, m_step};
    m_points.aliveCount -=
        deleteParticles(m_points.set, m_step <= 1 ? nullptr : &m_points.evolving.items(),
                        m_deletion, m_scene, clock, m_ledger);
    if (m_fe) {
        deleteFreeNodes(m_fe->solid().nodes(), m_deletion, m_scene, clock, m_ledger);
    }
}

Totals Simulation::totals() const {
    return m_ledger.totals(m_points.set, finiteElements(), contact(), activeCount());
}

double Simulation::energyError() const {
    return m_ledger.energyError(totals());
}

void Simulation::updateProgress() {
    m_stop->update(m_time, m_points.set, m_fe ? &m_fe->solid().nodes() : nullptr);
    if (m_rearWall && m_stop->awaitsRearWallConfirmation() && m_time >= m_nextRearWallCheck) {
        m_nextRearWallCheck = m_time + kRearWallCheckEveryUs;
        if (m_rearWall->perforated(m_time, m_step, m_points.set, finiteElements())) {
            m_stop->confirmRearWallPerforation();
        }
    }
}

void Simulation::save(io::CheckpointState& s) const {
    s.timeUs = m_time;
    s.step = m_step;
    m_loop.save(s);
    const Ledger::Account& account = m_ledger.account();
    s.extra["dt_us"] = m_dt;
    s.extra["initial_energy_J"] = account.initialEnergy;
    // The ledger's own share: the eroded elements' energy and the free nodes' heat are kept
    // by the FE and contact packages.
    s.extra["deleted_energy_J"] = account.deletedEnergy;
    s.extra["deleted_mass_mg"] = account.deletedMass;
    s.extra["deleted_momentum_z"] = account.deletedMomentumZ;
    s.extra["runaway_deleted"] = account.runaway;
    s.extra["out_of_domain_deleted"] = account.outOfDomain;
    s.extra["rear_wall_confirmed"] = m_stop->rearWallConfirmed();
    s.extra["next_rear_wall_check_us"] = m_nextRearWallCheck;
}

void Simulation::restore(const io::CheckpointState& s) {
    m_time = s.timeUs;
    m_step = s.step;
    m_dt = s.extra.at("dt_us");
    Ledger::Account account;
    account.initialEnergy = s.extra.at("initial_energy_J");
    account.deletedEnergy = s.extra.at("deleted_energy_J");
    account.deletedMass = s.extra.at("deleted_mass_mg");
    account.deletedMomentumZ = s.extra.at("deleted_momentum_z");
    account.runaway = s.extra.at("runaway_deleted");
    account.outOfDomain = s.extra.at("out_of_domain_deleted");
    m_ledger.restore(account);
    m_loop.restore(s);
    m_points.countAlive();
    m_nextRearWallCheck = s.extra.value("next_rear_wall_check_us", 0.0);
    if (s.extra.value("rear_wall_confirmed", false)) {
        m_stop->confirmRearWallPerforation();
    }
    updateProgress();
}

} // namespace hvi::solver
