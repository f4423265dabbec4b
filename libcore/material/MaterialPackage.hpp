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
#include <span>
#include <vector>

namespace hvi::material {

/// What one body needs from its material, chosen once.
struct BodyMaterial {
    const material::MaterialSpec* spec = nullptr;
    bool strength = false;   ///< the body carries deviatoric stress (material and scene agree)
    double minDensity = 0.0; ///< below it a particle carries no stress [g/cm^3]
    double maxDensity = 0.0; ///< particle density ceiling [g/cm^3] (densityCeiling())
    std::size_t first = 0, count = 0; ///< index range in the body's point set (particles or
                                      ///< elements; count 0 in the other set)
};

/// The largest density a particle of this material may reach [g/cm^3]. Mie-Grueneisen: where
/// the Hugoniot denominator 1 - (s - 1) mu falls to 1/2, rho0 (1 + 1 / (2 (s - 1))): 2.25 rho0
/// for Al 6061-T6, 2.0 rho0 for steel 4340, above every shocked state a 15 km/s impact of
/// these materials reaches (Al on Al: 1.9 rho0) and far beyond where a linear Us-up fit
/// holds. Particles with too few neighbours for a sound density estimate (lone debris pressed
/// against a surface by contact) otherwise compress without bound and stall the time step.
/// Other equations of state: no ceiling (+inf), e.g. the ideal gas of the Noh problem
/// legitimately reaches 16 rho0.
double densityCeiling(const material::MaterialSpec& spec);

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
    /// The same for the listed points only (ascending indices), e.g. the elements an FE
    /// update evaluated: the rest keep their pressure. The loops over a list are threaded
    /// only when it is long (parallelFor), so a caller may pass short slices from its own
    /// parallel region.
    template <class Points>
    void updatePressure(Points& points, std::span<const int32_t> sortedItems) const;

    /// dS/dt (Jaumann rate with the hoop strain rate) for the points listed.
    template <class Points, class Rates>
    void addStressRates(const Points& points, std::span<const int32_t> active, Rates& rates) const;

    /// Radial return onto the Johnson-Cook yield surface, plastic strain, damage
    /// accumulation (over the step dt [us]) and the failed / under-dense states, after the
    /// deviator was updated.
    template <class Points, class Rates>
    void applyPlasticity(Points& points, const Rates& rates, std::span<const int32_t> active,
                         double dt) const;
    /// The same over a step of each point's own, steps[i] [us] (time-step bins).
    template <class Points, class Rates>
    void applyPlasticity(Points& points, const Rates& rates, std::span<const int32_t> active,
                         const std::vector<double>& steps) const;

    const std::vector<BodyMaterial>& bodies() const { return m_bodies; }

private:
    template <class Points, class Rates, class StepOf>
    void plasticity(Points& points, const Rates& rates, std::span<const int32_t> active,
                    StepOf&& stepOf) const;

    std::vector<BodyMaterial> m_bodies;
};

} // namespace hvi::material
