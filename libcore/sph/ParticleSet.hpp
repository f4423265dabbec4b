// Structure-of-arrays storage of SPH particles in the (z, r) plane.
//
// Units: the hydrocode system of docs/conventions.md: mm, us, mg, so velocity km/s,
// density g/cm^3 (= mg/mm^3), pressure and stress GPa, specific energy MJ/kg (= J/mg).
// `mass` is the true (3D) mass of the ring a particle stands for in axisymmetric mode
// (2 pi r rho dA), and the mass per unit depth in planar mode.
//
// Strength arrays (stress deviator, plastic strain, damage and its state) are allocated only
// when some body in the scene has strength: a purely hydrodynamic scene carries none of them.
#pragma once

#include "core/FieldList.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hvi::sph {

struct ParticleSet {
    // State.
    std::vector<double> z, r;         ///< position [mm]
    std::vector<double> vz, vr;       ///< velocity [km/s]
    std::vector<double> mass;         ///< [mg]
    std::vector<double> h;            ///< smoothing length [mm]
    std::vector<double> rho;          ///< density [g/cm^3]
    std::vector<double> e;            ///< specific internal energy [MJ/kg]
    std::vector<double> p;            ///< pressure [GPa] (from the EOS)
    std::vector<double> cs;           ///< sound speed [km/s] (from the EOS, with strength)
    std::vector<int32_t> body;        ///< index into the scene's body list
    std::vector<uint8_t> alive;       ///< 0 once deleted (runaway, left the domain)

    // Strength (empty when no body has strength).
    std::vector<double> szz, srr, srz; ///< stress deviator in the (z, r) plane [GPa]
    std::vector<double> plasticStrain; ///< equivalent plastic strain [-]
    std::vector<double> damage;        ///< Johnson-Cook damage D in [0, 1] [-]
    std::vector<double> tensionOnset;  ///< damage state (JohnsonCookDamage::damageAfter) [-]

    bool hasStrength() const { return m_withStrength; }
    std::size_t size() const { return z.size(); }

    /// Appends one particle at rest state (strength arrays follow `withStrength`).
    void add(double zMm, double rMm, double vzKmS, double vrKmS, double massMg, double hMm,
             double rhoGcc, double eMJkg, int32_t bodyIndex);

    /// Allocates the strength arrays (zero) for every particle, present and added later.
    void enableStrength();

private:
    bool m_withStrength = false;
};

/// The evolved state every particle carries (p and cs follow from it; body and alive are
/// integer fields), by checkpoint name.
inline constexpr std::array<Field<ParticleSet>, 8> kParticleStateFields{{
    {"z", &ParticleSet::z},
    {"r", &ParticleSet::r},
    {"vz", &ParticleSet::vz},
    {"vr", &ParticleSet::vr},
    {"mass", &ParticleSet::mass},
    {"h", &ParticleSet::h},
    {"rho", &ParticleSet::rho},
    {"e", &ParticleSet::e},
}};
/// The strength state (allocated only when some body has strength); the same names, in the
/// same order, as fe::kElementStrengthFields, which an eroded element hands to its particle.
inline constexpr std::array<Field<ParticleSet>, 6> kParticleStrengthFields{{
    {"szz", &ParticleSet::szz},
    {"srr", &ParticleSet::srr},
    {"srz", &ParticleSet::srz},
    {"plastic_strain", &ParticleSet::plasticStrain},
    {"damage", &ParticleSet::damage},
    {"tension_onset", &ParticleSet::tensionOnset},
}};

/// A particle slot that holds no material: one held in reserve for an FE element that has not
/// eroded yet (solver/ErodedParticles.hpp). Not alive and massless; a deleted particle keeps
/// its mass. The one definition for the solver, the run file and hvi-assess.
inline bool isUnusedSlot(uint8_t alive, double mass) {
    return !alive && mass == 0.0;
}

/// Time derivatives of the evolved fields, filled by the physics packages.
struct ParticleRates {
    std::vector<double> az, ar;       ///< acceleration [km/s/us]
    std::vector<double> drho;         ///< [g/cm^3/us]
    std::vector<double> de;           ///< [MJ/kg/us]
    std::vector<double> dh;           ///< [mm/us]
    std::vector<double> dszz, dsrr, dsrz; ///< deviator rate [GPa/us]
    std::vector<double> strainRate;   ///< equivalent total strain rate [1/us]
    // Corrected velocity gradient and hoop strain rate (for the strength package).
    std::vector<double> dvzDz, dvzDr, dvrDz, dvrDr; ///< [1/us]
    std::vector<double> hoopRate;                   ///< D_thth = v_r / r (regularised) [1/us]

    void resize(std::size_t n, bool withStrength);
    void zero();
    /// Zeroes the rates of the listed particles only (the others are known to be zero).
    void zero(const std::vector<int32_t>& items);
};

/// The rates a checkpoint carries (the next step's first kick uses them), by checkpoint
/// name; the second list only with strength.
inline constexpr std::array<Field<ParticleRates>, 5> kRateFields{{
    {"az", &ParticleRates::az},
    {"ar", &ParticleRates::ar},
    {"drho", &ParticleRates::drho},
    {"de", &ParticleRates::de},
    {"dh", &ParticleRates::dh},
}};
inline constexpr std::array<Field<ParticleRates>, 3> kStrengthRateFields{{
    {"dszz", &ParticleRates::dszz},
    {"dsrr", &ParticleRates::dsrr},
    {"dsrz", &ParticleRates::dsrz},
}};

/// What the leapfrog integrates (solver/HalfStep.hpp): each evolved field with its rate, in
/// the order of its half-step arrays; the second list only with strength.
struct IntegratedField {
    std::vector<double> ParticleSet::*state;
    std::vector<double> ParticleRates::*rate;
};
inline constexpr std::array<IntegratedField, 5> kIntegratedFields{{
    {&ParticleSet::vz, &ParticleRates::az},
    {&ParticleSet::vr, &ParticleRates::ar},
    {&ParticleSet::e, &ParticleRates::de},
    {&ParticleSet::rho, &ParticleRates::drho},
    {&ParticleSet::h, &ParticleRates::dh},
}};
inline constexpr std::array<IntegratedField, 3> kIntegratedStrengthFields{{
    {&ParticleSet::szz, &ParticleRates::dszz},
    {&ParticleSet::srr, &ParticleRates::dsrr},
    {&ParticleSet::srz, &ParticleRates::dsrz},
}};

} // namespace hvi::sph
