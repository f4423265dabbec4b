// The material pipeline of SPH particles: equation of state, Johnson-Cook strength with
// radial return, Johnson-Cook damage, the minimum-density cut-off. One implementation of each
// model lives in libcore/material; this package only loops over a body's particles with the
// models that body chose (std::visit once per body, never per particle).
//
// Order within a step (see Simulation): pressures for the state the forces are computed
// from; deviatoric rates from the corrected velocity gradient (Jaumann, with the hoop strain
// rate); after the update, the plastic correction and damage.
//
// Units: GPa, g/cm^3, MJ/kg, 1/us (docs/conventions.md).
#pragma once

#include "material/MaterialSpec.hpp"
#include "sph/ParticleSet.hpp"

#include <vector>

namespace hvi::solver {

/// What one body needs from its material, chosen once.
struct BodyMaterial {
    const material::MaterialSpec* spec = nullptr;
    bool strength = false;    ///< the body carries deviatoric stress (material and scene agree)
    double minDensity = 0.0;  ///< below it a particle carries no stress [g/cm^3]
    std::size_t first = 0, count = 0; ///< particle index range
};

class MaterialPackage {
public:
    explicit MaterialPackage(std::vector<BodyMaterial> bodies) : m_bodies(std::move(bodies)) {}

    /// p and cs for every alive particle from (rho, e); the sound speed includes the shear
    /// contribution (c^2 = K/rho + 4G/(3 rho)) for bodies with strength, since that is the
    /// fastest signal the time step must resolve.
    void updatePressure(sph::ParticleSet& particles) const;

    /// dS/dt (Jaumann rate with the hoop strain rate) for the particles listed.
    void addStressRates(const sph::ParticleSet& particles, const std::vector<int32_t>& active,
                        sph::ParticleRates& rates) const;

    /// Radial return onto the Johnson-Cook yield surface, plastic strain, damage
    /// accumulation and the failed / under-dense states, after an update of length dt [us].
    void applyPlasticity(sph::ParticleSet& particles, const sph::ParticleRates& rates,
                         const std::vector<int32_t>& active) const;

    const std::vector<BodyMaterial>& bodies() const { return m_bodies; }

private:
    std::vector<BodyMaterial> m_bodies;
};

} // namespace hvi::solver
