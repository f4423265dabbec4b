// The finite-element package of the time loop (solver/Package.hpp): the nodes' kicks and
// drift, the element update (fe/FeSolid.hpp, central difference with the half-step node
// velocities) over the element material pipeline, and, when the scene says so, the hand-over
// of the elements that eroded in a step to the SPH particles they become
// (solver/ErodedParticles.hpp).
//
// With time-step bins (scene fe.time_stepping: bins) each element steps over an interval of
// 2^k base steps from its own stable step, with the interval logic of solver/TimeBins.hpp
// (the wake-up bounds the bins of the elements that share a node with an evaluated one). The
// nodes drift and take the contact every base step; an element's force acts on its nodes as
// impulses at its interval's ends, half its interval times its force at each (multiple time
// stepping in impulse form, r-RESPA: Tuckerman, Berne & Martyna, J. Chem. Phys. 97 (1992)
// 1990; for explicit FE subcycling, Belytschko, Yen & Mullen, CMAME 17/18 (1979) 259). For
// one element alone that is the leapfrog over its interval, stable below its own step; with
// every element in the first bin it is the global step, bit for bit. Its update takes the
// strain increment of its corners' displacement over the interval (fe/FeSolid.hpp).
//
// Units: mm, us, mg (km/s, g/cm^3, J).
#pragma once

#include "fe/FeSolid.hpp"
#include "material/MaterialPackage.hpp"
#include "solver/ErodedParticles.hpp"
#include "solver/Package.hpp"
#include "solver/ParticleState.hpp"
#include "solver/SceneAssembly.hpp"
#include "solver/TimeBins.hpp"

#include <memory>
#include <vector>

namespace hvi::solver {

class FePackage final : public Package {
public:
    /// The FE bodies of `assembly` (solver/SceneAssembly.hpp); the particles their eroded
    /// elements become (if any) take the densities of `particles`' bodies' own bounds.
    /// With `timeBins`, elements step in bins of their own stable step times `cfl`.
    FePackage(const fe::FeOptions& options, FeAssembly assembly, ParticleState& points,
              const material::MaterialPackage& particles, bool timeBins = false,
              double cfl = 0.0);

    const char* name() const override { return "fe"; }
    double stableTimeStep() const override { return m_solid.stableTimeStep(); }
    /// Empty with time-step bins (the last update covered only the elements it closed).
    std::span<const double> pointSteps() const override {
        return m_binned ? std::span<const double>{} : std::span<const double>{m_solid.elementSteps()};
    }
    void kick(double dt) override;
    void drift(double dt) override;
    void evaluate(double dt) override;
    void kickAgain(double dt) override;
    void finish(double dt) override;
    void prepare(double dtGuess) override;
    void save(io::CheckpointState& state) const override;
    void restore(const io::CheckpointState& state) override;

    /// With time-step bins, the elements of nodes that contact pushed in this step take the
    /// first bin from the next step on: an element in a longer interval would not feel the
    /// push until the interval ends, while the contact keeps pushing.
    void wakeAtNodes(std::span<const int32_t> nodes);

    fe::FeSolid& solid() { return m_solid; }
    const fe::FeSolid& solid() const { return m_solid; }

private:
    void kickNodes(double dt);
    /// Time-step bins: the elements whose interval opens or was shortened this step, and the
    /// weights of their forces in the first kick (solver/TimeBins.hpp).
    void openIntervals(double dt);
    /// The elements that close their interval or woke this step: advanced, voting, waking
    /// their neighbours, and weighted for the second kick.
    void closeIntervals(double dt);
    /// m_list := the union of two ascending lists, m_weight the sum of their weights.
    template <class WeightA, class WeightB>
    void mergeWeighted(std::span<const int32_t> a, WeightA&& weightA, std::span<const int32_t> b,
                       WeightB&& weightB);
    /// The elements the last update eroded become particles, evolving from the next step.
    void convertErodedElements();

    bool m_axisymmetric;
    fe::FeSolid m_solid;
    material::MaterialPackage m_materials;
    std::unique_ptr<ErodedParticles> m_eroded;
    ParticleState& m_points;
    std::vector<double> m_rhoMin, m_rhoMax;
    bool m_binned = false;
    double m_cfl = 0.0;
    TimeBins m_bins;
    std::vector<double> m_intervalStart; ///< 8 per element: corner (z, r) at its interval's start
    std::vector<int32_t> m_list;         ///< elements weighted in this kick (ascending)
    std::vector<double> m_weight;        ///< their weights: impulse / (dt/2 force)
};

} // namespace hvi::solver
