// The SPH package of the time loop (solver/Package.hpp): the hydrodynamic rates
// (sph/SphHydro.hpp) and the particle material pipeline (material/MaterialPackage.hpp) over
// the evolving particles, their leapfrog over the integrated field list
// (solver/HalfStep.hpp), and the particle-only rules of the step: reflection at the axis,
// the density and smoothing-length clamps.
//
// Units: mm, us, mg (km/s, GPa, g/cm^3, MJ/kg).
#pragma once

#include "material/MaterialPackage.hpp"
#include "scene/Scene.hpp"
#include "solver/Package.hpp"
#include "solver/ParticleState.hpp"
#include "solver/TimeBins.hpp"
#include "sph/NeighbourSearch.hpp"
#include "sph/ParticleGenerator.hpp"
#include "sph/SphHydro.hpp"

#include <memory>
#include <vector>

namespace hvi::solver {

class SphPackage final : public Package {
public:
    /// `fills` and `specs`: one per body of the scene, kept by the caller for the package's
    /// lifetime; `bodies`: each body's particles and material.
    SphPackage(const scene::Scene& scene, ParticleState& points,
               const std::vector<sph::BodyFill>& fills,
               const std::vector<material::MaterialSpec>& specs,
               std::vector<material::BodyMaterial> bodies, bool skipDormant);

    const char* name() const override { return "sph"; }
    double stableTimeStep() const override {
        return m_binned ? m_binVote : m_hydro.stableTimeStep();
    }
    /// Empty with time-step bins (the last evaluation covered only the particles it closed).
    std::span<const double> pointSteps() const override {
        return m_binned ? std::span<const double>{} : m_hydro.particleSteps();
    }
    void kick(double dt) override;
    void drift(double dt) override;
    void evaluate(double dt) override;
    void kickAgain(double dt) override;
    void finish(double dt) override;
    void prepare(double dtGuess) override;
    void save(io::CheckpointState& state) const override;
    void restore(const io::CheckpointState& state) override;

    /// The particle whose stability limit set the last vote (-1 if none).
    int32_t limitingParticle() const {
        return m_binned ? m_binLimiter : m_hydro.limitingParticle();
    }
    /// The particles whose rates the last step evaluated (all active ones without bins).
    std::size_t evaluatedCount() const {
        return m_binned ? m_evaluatedActive.size() : m_neighbours.active.size();
    }
    const sph::NeighbourList& neighbours() const { return m_neighbours; }
    /// The pairs of the last evaluation (inside the support; computed, with the padding).
    const sph::PairCounts& pairCounts() const { return m_hydro.pairCounts(); }
    const material::MaterialPackage& materials() const { return m_materials; }

private:
    /// Neighbour list, hydro rates and stress rates at the current state; the particles the
    /// evaluation activates join the evolving set.
    void computeRates(double dt);
    /// computeRates with time-step bins: the particles whose interval ends in this base step
    /// of length dt [us] (solver/TimeBins.hpp), their votes and their neighbours' wake-up.
    void computeBinnedRates(double dt);
    /// Half-step arrays := state, no particle evolving, the next evaluation repacks all.
    void resetHalfStep();
    void clampSmoothingLengths();
    /// The compatible energy update of a half kick just made (sph/PairWork.hpp): each
    /// particle of the last evaluation takes its heating at the mean of its velocities before
    /// and after the kick, into the half-step energy (the first kick) or the state's (the
    /// second).
    enum class Kick { First, Second };
    void payPairWork(Kick which, double halfDt);

    const scene::Scene& m_scene;
    ParticleState& m_points;
    const std::vector<sph::BodyFill>& m_fills;
    const std::vector<material::MaterialSpec>& m_specs;
    material::MaterialPackage m_materials;
    sph::SphHydro m_hydro;
    sph::NeighbourList m_neighbours;
    sph::NeighbourSearchOptions m_searchOptions;
    bool m_packAll = true; ///< the next evaluation repacks every particle
    std::vector<double> m_meanVz, m_meanVr; ///< a half kick's mean velocities (payPairWork)
    bool m_binned = false; ///< time-step bins (scene sph.time_stepping)
    TimeBins m_bins;
    std::vector<int32_t> m_dueSlots;        ///< slots of the active list evaluated this step
    std::vector<int32_t> m_evaluatedActive; ///< their particles
    std::vector<int32_t> m_evaluated;       ///< every particle whose rates were renewed
    double m_binVote = 0.0;                 ///< the smallest vote [us]
    int32_t m_binLimiter = -1;
};

} // namespace hvi::solver
