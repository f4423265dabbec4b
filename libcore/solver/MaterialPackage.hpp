// The material pipeline of SPH particles and finite elements alike: equation of state,
// Johnson-Cook strength with radial return, Johnson-Cook damage, the minimum-density cut-off.
// One implementation of each model lives in libcore/material; this package only loops over a
// body's material points (particles or element integration points: sph::ParticleSet and
// fe::ElementSet share the field names) with the models that body chose (std::visit once per
// body, never per point).
//
// Order within a step (see Simulation): pressures for the state the forces are computed
// from; deviatoric rates from the corrected velocity gradient (Jaumann, with the hoop strain
// rate); after the update, the plastic correction and damage.
//
// Units: GPa, g/cm^3, MJ/kg, 1/us (docs/conventions.md).
#pragma once

#include "material/MaterialSpec.hpp"

#include <cstdint>
#include <vector>

namespace hvi::solver {

/// What one body needs from its material, chosen once.
struct BodyMaterial {
    const material::MaterialSpec* spec = nullptr;
    bool strength = false;    ///< the body carries deviatoric stress (material and scene agree)
    double minDensity = 0.0;  ///< below it a particle carries no stress [g/cm^3]
    std::size_t first = 0, count = 0; ///< index range in the body's point set (particles or
                                      ///< elements; count 0 in the other set)
};

class MaterialPackage {
public:
    explicit MaterialPackage(std::vector<BodyMaterial> bodies) : m_bodies(std::move(bodies)) {}

    /// p and cs for every alive particle from (rho, e); the sound speed includes the shear
    /// contribution (c^2 = K/rho + 4G/(3 rho)) for bodies with strength, since that is the
    /// fastest signal the time step must resolve.
    /// `Points` is sph::ParticleSet or fe::ElementSet, `Rates` sph::ParticleRates or
    /// fe::ElementRates (explicitly instantiated for those pairs).
    template <class Points>
    void updatePressure(Points& points) const;

    /// dS/dt (Jaumann rate with the hoop strain rate) for the points listed.
    template <class Points, class Rates>
    void addStressRates(const Points& points, const std::vector<int32_t>& active,
                        Rates& rates) const;

    /// Radial return onto the Johnson-Cook yield surface, plastic strain, damage
    /// accumulation and the failed / under-dense states, after the deviator was updated.
    template <class Points, class Rates>
    void applyPlasticity(Points& points, const Rates& rates,
                         const std::vector<int32_t>& active) const;

    const std::vector<BodyMaterial>& bodies() const { return m_bodies; }

private:
    std::vector<BodyMaterial> m_bodies;
};

} // namespace hvi::solver
