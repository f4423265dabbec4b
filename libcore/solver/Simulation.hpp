// The explicit time loop: it composes the physics packages (solver/Package.hpp: SPH hydro,
// finite elements, contact), takes the smallest time step any of them asks for, runs each
// phase of the step over all of them, and applies the deletion rule (solver/DeletionRule.hpp),
// the conservation ledger (solver/Ledger.hpp) and the stop rules (solver/StopRules.hpp). No
// physics lives here; see the packages. A scene without FE bodies has neither the FE nor the
// contact package.
//
// Integrator: kick-drift-kick leapfrog with a predicted end-of-step state (velocity Verlet in
// the form used by Monaghan 2005, Rep. Prog. Phys. 68:1703, section 8.1), one rate evaluation
// per step:
//   half kick with the rates of step n; drift positions a full step; predict the end-of-step
//   state with the same rates; evaluate rates there; second half kick with the new rates.
// FE nodes take the same kicks and drift; contact constrains the half-step velocities of
// particles and nodes before the drift; the elements are updated with the half-step node
// velocities (central difference). Elements that erode in a step become SPH particles at its
// end (solver/ErodedParticles.hpp), unless the scene keeps their mass on free nodes.
// Time step: dt = cfl * min(package votes), grown by at most 25 % per step (a sudden jump in
// dt after a quiet phase would skip the first steps of a new contact).
//
// Units: mm, us, mg (km/s, GPa, g/cm^3, MJ/kg, J); see docs/conventions.md.
#pragma once

#include "io/Checkpoint.hpp"
#include "material/MaterialLibrary.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneLibrary.hpp"
#include "solver/ContactPackage.hpp"
#include "solver/DeletionRule.hpp"
#include "solver/FePackage.hpp"
#include "solver/Ledger.hpp"
#include "solver/PackageLoop.hpp"
#include "solver/ParticleState.hpp"
#include "solver/RearWallConfirmation.hpp"
#include "solver/SphPackage.hpp"
#include "solver/StopRules.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hvi::solver {

struct SimulationOptions {
    bool skipDormant = true; ///< the dormant-region optimisation (exact; off only for tests)
};

class Simulation {
public:
    Simulation(const scene::Scene& scene, const material::MaterialLibrary& library,
               SimulationOptions options = {});
    // The packages hold references into the simulation (its scene, its particle state).
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    /// One time step. Throws RuntimeFailure if the state stops being finite.
    void advance();

    double time() const { return m_time; }
    long step() const { return m_step; }
    double lastDt() const { return m_dt; }
    const sph::ParticleSet& particles() const { return m_points.set; }
    sph::ParticleSet& particles() { return m_points.set; }
    const scene::Scene& scene() const { return m_scene; }
    const std::vector<sph::BodyFill>& bodyFills() const { return m_fills; }
    /// The particles whose rates the last step evaluated (with time-step bins, those whose
    /// interval it closed).
    std::size_t activeCount() const { return m_sph->evaluatedCount(); }
    std::size_t aliveCount() const { return m_points.aliveCount; }
    /// The particles the steps integrate (every one that has moved since the start).
    std::size_t evolvingCount() const { return m_points.evolving.size(); }
    /// The particle whose stability limit set the SPH vote (-1 if none).
    int32_t dtLimitingParticle() const { return m_sph->limitingParticle(); }
    /// The SPH package's time-step vote before the Courant factor [us].
    double sphStableTimeStep() const { return m_sph->stableTimeStep(); }
    std::size_t pairCount() const { return m_sph->neighbours().pairCount(); }
    /// The SPH pairs of the last evaluation: inside the support, and computed.
    const sph::PairCounts& evaluatedPairs() const { return m_sph->pairCounts(); }
    /// The FE solid, null in a scene without FE bodies.
    const fe::FeSolid* finiteElements() const { return m_fe ? &m_fe->solid() : nullptr; }
    fe::FeSolid* finiteElements() { return m_fe ? &m_fe->solid() : nullptr; }
    const contact::KinematicContact* contact() const {
        return m_contact ? &m_contact->contact() : nullptr;
    }
    contact::KinematicContact* contact() { return m_contact ? &m_contact->contact() : nullptr; }
    /// Wall time spent so far in each package's phases [s] (the benchmark's throughput
    /// figures); the deletion pass counts as SPH here.
    struct PackageSeconds {
        double sph = 0.0, fe = 0.0, contact = 0.0;
    };
    PackageSeconds packageSeconds() const;
    /// The package whose vote set the last time step ("sph", "fe", "contact").
    const std::string& dtLimiter() const { return m_dtLimiter; }
    /// Each package's wall time so far by phase and section, in loop order (the run's
    /// profile, solver/Profile.hpp).
    std::vector<std::pair<std::string, PhaseTimes>> packageTimes() const { return m_loop.times(); }
    /// What time-step bins would have evaluated, per package with points (BinnedWork.hpp).
    std::vector<std::pair<std::string, BinnedWork>> binnedWork() const {
        return m_loop.binnedWork();
    }
    /// Wall time of the simulation's own work between steps [s]: deleting points, and the stop
    /// rules with the rear-wall confirmation they ask for.
    double deletionSeconds() const { return m_deletionSeconds; }
    double stopRuleSeconds() const { return m_stopRuleSeconds; }
    /// Starts the wall-time accounts above afresh (a run's profile covers the run alone, not
    /// the preparation at construction).
    void resetTimes();

    Totals totals() const;
    double initialEnergy() const { return m_ledger.account().initialEnergy; }
    /// (E + E_deleted - E0) / E0 [-].
    double energyError() const;
    const Ledger& ledger() const { return m_ledger; }

    /// The stop rule that fires now, if any ("end_time", "debris_stopped",
    /// "no_new_penetration", "rear_wall_perforated", "max_steps").
    std::optional<std::string> stopReason() const { return m_stop->reason(m_time, m_step); }
    /// Bodies penetrated so far (material of another body behind their rear face).
    const std::vector<uint8_t>& penetrated() const { return m_stop->penetrated(); }
    double lastProgressTime() const { return m_stop->lastProgressTime(); }

    /// Counters of deletions by reason.
    std::size_t runawayDeleted() const { return m_ledger.account().runaway; }
    std::size_t outOfDomainDeleted() const { return m_ledger.account().outOfDomain; }

    /// The rates of the last step (the first kick of the next step uses them).
    const sph::ParticleRates& rates() const { return m_points.rates; }
    /// Recomputes what the next step reads from the state (pressures, rates, forces, votes)
    /// after the particle arrays were replaced.
    void refreshRates();

    /// The run's state into a checkpoint: the clock, the ledger's account and each package's
    /// state (io/Checkpoint.hpp; the caller adds what the run loop keeps).
    void save(io::CheckpointState& state) const;
    /// Back from a checkpoint of the same scene; throws InputError when it does not fit.
    void restore(const io::CheckpointState& state);

private:
    /// The time step: the smallest package vote times the Courant factor, grown by at most
    /// kMaxDtGrowth, ending on the end time.
    double nextTimeStep();
    void deletePoints();
    void updateProgress();

    scene::Scene m_scene;
    std::vector<material::MaterialSpec> m_specs; ///< one per body (BodyMaterial::spec)
    std::vector<sph::BodyFill> m_fills;          ///< one per body
    double m_minSpacing = 0.0;
    ParticleState m_points;
    std::unique_ptr<SphPackage> m_sph;
    std::unique_ptr<FePackage> m_fe;           ///< null without FE bodies
    std::unique_ptr<ContactPackage> m_contact; ///< null without FE bodies
    PackageLoop m_loop;                        ///< SPH, FE, contact
    std::string m_dtLimiter = "sph";
    double m_deletionSeconds = 0.0;
    double m_stopRuleSeconds = 0.0;

    double m_time = 0.0;
    long m_step = 0;
    double m_dt = 0.0;
    Ledger m_ledger;
    DeletionRule m_deletion;
    std::unique_ptr<StopRules> m_stop;
    std::unique_ptr<RearWallConfirmation> m_rearWall; ///< asked while the stop rule waits
    double m_nextRearWallCheck = 0.0;                 ///< [us]
};

} // namespace hvi::solver
