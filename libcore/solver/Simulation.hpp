// The explicit time loop: it composes the physics packages (SPH hydro, finite elements, the
// material pipeline they share, contact), takes the smallest time step any of them asks for,
// and applies the deletion rule (solver/DeletionRule.hpp), the conservation ledger
// (solver/Ledger.hpp) and the stop rules (solver/StopRules.hpp). No physics lives here; see
// the packages. A scene without FE bodies allocates nothing of the FE and contact packages.
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

#include "contact/KinematicContact.hpp"
#include "fe/FeSolid.hpp"
#include "material/MaterialLibrary.hpp"
#include "material/MaterialPackage.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneLibrary.hpp"
#include "solver/DeletionRule.hpp"
#include "solver/ErodedParticles.hpp"
#include "solver/HalfStep.hpp"
#include "solver/Ledger.hpp"
#include "solver/StopRules.hpp"
#include "sph/NeighbourSearch.hpp"
#include "sph/ParticleGenerator.hpp"
#include "sph/SphHydro.hpp"

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

    /// One time step. Throws RuntimeFailure if the state stops being finite.
    void advance();

    double time() const { return m_time; }
    long step() const { return m_step; }
    double lastDt() const { return m_dt; }
    const sph::ParticleSet& particles() const { return m_particles; }
    sph::ParticleSet& particles() { return m_particles; }
    const scene::Scene& scene() const { return m_scene; }
    const std::vector<sph::BodyFill>& bodyFills() const { return m_fills; }
    std::size_t activeCount() const { return m_neighbours.active.size(); }
    std::size_t aliveCount() const { return m_aliveCount; }
    /// The particle whose stability limit set the last time step (-1 if none).
    int32_t dtLimitingParticle() const { return m_hydro->limitingParticle(); }
    /// The SPH package's time-step vote before the Courant factor [us].
    double sphStableTimeStep() const { return m_hydro->stableTimeStep(); }
    std::size_t pairCount() const { return m_neighbours.pairCount(); }
    /// The FE package, null in a scene without FE bodies.
    const fe::FeSolid* finiteElements() const { return m_fe.get(); }
    fe::FeSolid* finiteElements() { return m_fe.get(); }
    const contact::KinematicContact* contact() const { return m_contact.get(); }
    contact::KinematicContact* contact() { return m_contact.get(); }
    /// Wall time spent so far in each package [s] (for the benchmark's throughput figures):
    /// SPH every particle loop of a step (kicks, drift, rates, material pipeline, deletion),
    /// FE the node kicks and drift, the element update and the eroded elements' conversion,
    /// contact the constraint alone.
    struct PackageSeconds {
        double sph = 0.0, fe = 0.0, contact = 0.0;
    };
    const PackageSeconds& packageSeconds() const { return m_packageSeconds; }
    /// The package whose limit set the last time step ("sph", "fe", "contact").
    const std::string& dtLimiter() const { return m_dtLimiter; }

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

    /// Where the run stands: what a checkpoint keeps besides the point sets' arrays.
    struct Clock {
        double time = 0.0; ///< [us]
        long step = 0;
        double dt = 0.0; ///< the last step [us]
    };
    /// The FE package's erosion account (eroded elements' energy [J] and count).
    struct ErosionAccount {
        double energy = 0.0;
        std::size_t count = 0;
    };
    /// Restores the clock and the ledger after a checkpoint's particle and FE arrays were
    /// loaded, and the derived state (pressures, neighbour lists); the caller then restores the
    /// rates (rates()) and the votes (restoreVotes), which depend on the step's predicted state.
    void restoreClock(const Clock& clock, const Ledger::Account& account,
                      const ErosionAccount& erosion);
    /// The rates of the last step (the first kick of the next step uses them; checkpointed).
    const sph::ParticleRates& rates() const { return m_rates; }
    sph::ParticleRates& rates() { return m_rates; }
    /// Restores, after restoreClock, what the next step reads from the last one: the SPH
    /// time-step vote, and with FE bodies the FE vote and the contact state.
    void restoreVotes(double sphDt, int32_t sphParticle, double feDt, int32_t feElement,
                      double contactDt, std::vector<uint8_t> contactFlags);
    /// Recomputes pressures and rates after the particle arrays were replaced.
    void refreshRates();

private:
    void computeRates();
    /// Half-step arrays := state, and no particle evolving (start of a run).
    void resetHalfStep();
    /// Adds particles to the evolving set, kept sorted without repeats.
    void includeEvolving(const std::vector<int32_t>& items);
    /// The time step: the smallest package vote times the Courant factor, grown by at most
    /// kMaxDtGrowth, ending on the end time.
    double nextTimeStep();
    void deletePoints();
    /// The elements the FE update eroded become particles (scene fe.eroded_material).
    void convertErodedElements(const HalfStep::Lanes& lanes);
    void clampSmoothingLengths();
    void updateProgress();
    void driftNodes(double dt);
    void kickNodes(double dt);

    scene::Scene m_scene;
    SimulationOptions m_options;
    sph::ParticleSet m_particles;
    sph::ParticleRates m_rates;
    sph::NeighbourList m_neighbours;
    sph::NeighbourSearchOptions m_searchOptions;
    std::unique_ptr<sph::SphHydro> m_hydro;
    std::unique_ptr<material::MaterialPackage> m_materials; ///< SPH bodies' material points
    std::unique_ptr<material::MaterialPackage>
        m_feMaterials; ///< FE bodies' elements (FE scenes only)
    std::unique_ptr<fe::FeSolid> m_fe;
    std::unique_ptr<contact::KinematicContact> m_contact;
    std::unique_ptr<ErodedParticles> m_eroded; ///< null unless eroded elements become particles
    std::string m_dtLimiter = "sph";
    PackageSeconds m_packageSeconds;
    std::vector<sph::BodyFill> m_fills;
    std::vector<material::MaterialSpec> m_specs; // owned copies, one per body

    double m_time = 0.0;
    long m_step = 0;
    double m_dt = 0.0;
    std::size_t m_aliveCount = 0;
    Ledger m_ledger;
    DeletionRule m_deletion;
    std::unique_ptr<StopRules> m_stop;
    double m_minSpacing = 0.0;

    // The evolving set: every particle that has been evaluated or pushed by contact since
    // the start (it only grows). The others have never moved, so the time-step loops skip
    // them exactly.
    std::vector<int32_t> m_evolving;
    std::vector<uint8_t> m_isEvolving;
    bool m_packAll = true; ///< the next SPH evaluation repacks every particle

    HalfStep m_half; ///< the leapfrog's half-step state
};

} // namespace hvi::solver
