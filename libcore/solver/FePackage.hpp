// The finite-element package of the time loop (solver/Package.hpp): the nodes' kicks and
// drift, the element update (fe/FeSolid.hpp, central difference with the half-step node
// velocities) over the element material pipeline, and, when the scene says so, the hand-over
// of the elements that eroded in a step to the SPH particles they become
// (solver/ErodedParticles.hpp).
//
// Units: mm, us, mg (km/s, g/cm^3, J).
#pragma once

#include "fe/FeSolid.hpp"
#include "material/MaterialPackage.hpp"
#include "solver/ErodedParticles.hpp"
#include "solver/Package.hpp"
#include "solver/ParticleState.hpp"
#include "solver/SceneAssembly.hpp"

#include <memory>
#include <vector>

namespace hvi::solver {

class FePackage final : public Package {
public:
    /// The FE bodies of `assembly` (solver/SceneAssembly.hpp); the particles their eroded
    /// elements become (if any) take the densities of `particles`' bodies' own bounds.
    FePackage(const fe::FeOptions& options, FeAssembly assembly, ParticleState& points,
              const material::MaterialPackage& particles);

    const char* name() const override { return "fe"; }
    double stableTimeStep() const override { return m_solid.stableTimeStep(); }
    std::span<const double> pointSteps() const override { return m_solid.elementSteps(); }
    void kick(double dt) override { kickNodes(dt); }
    void drift(double dt) override;
    void evaluate(double dt) override { m_solid.update(dt, m_materials); }
    void kickAgain(double dt) override;
    void prepare(double dtGuess) override;
    void save(io::CheckpointState& state) const override;
    void restore(const io::CheckpointState& state) override;

    fe::FeSolid& solid() { return m_solid; }
    const fe::FeSolid& solid() const { return m_solid; }

private:
    void kickNodes(double dt);
    /// The elements the last update eroded become particles, evolving from the next step.
    void convertErodedElements();

    bool m_axisymmetric;
    fe::FeSolid m_solid;
    material::MaterialPackage m_materials;
    std::unique_ptr<ErodedParticles> m_eroded;
    ParticleState& m_points;
    std::vector<double> m_rhoMin, m_rhoMax;
};

} // namespace hvi::solver
