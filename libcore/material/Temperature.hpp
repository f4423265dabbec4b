// Temperature estimate for the Johnson-Cook thermal-softening terms (strength and failure).
//
// T = T_room + e / c_v, floored at 0 K, and the homologous temperature
// T* = (T - T_room) / (T_melt - T_room) clamped to [0, 1].
// (Johnson & Cook 1983, "A constitutive model and data for metals subjected to large strains,
// high strain rates and high temperatures", Proc. 7th Int. Symp. Ballistics, The Hague,
// define T* this way; the clamp to [0, 1] is ours: below room temperature the JC fits were
// not calibrated, and at or above melt the flow stress must be zero, not negative.)
//
// Why this simple form, and what it gets wrong: e is the whole specific internal energy
// measured from the reference state (rho0, T_room, e = 0), so it also counts the elastic
// (cold) compression energy as heat. Behind a strong shock that overestimates T and so
// softens the material early; in tension (e < 0 from cold expansion) T* clamps at 0.
// Subtracting the EOS cold-compression energy from e would remove the first error; that is a
// possible refinement, left out so that temperature needs nothing but e and three constants.
// c_v is taken as the tabulated specific heat (for metals near room temperature c_p and c_v
// differ by a few per cent).
//
// Units: e MJ/kg, c_v MJ/(kg K) (JSON carries J/(kg K); hvi::units::jPerKgKToMjPerKgK), T K.
#pragma once

#include <algorithm>

namespace hvi::material {

struct ThermalParams {
    double specificHeat = 0.0;    ///< c_v [MJ/(kg K)], > 0
    double roomTemperature = 0.0; ///< T_room [K]: the reference state's temperature
    double meltTemperature = 0.0; ///< T_melt [K], > T_room

    /// T [K] from specific internal energy e [MJ/kg]; never below 0 K.
    double temperature(double specificEnergy) const noexcept {
        const double t = roomTemperature + specificEnergy / specificHeat;
        return t < 0.0 ? 0.0 : t;
    }

    /// T* in [0, 1] from a temperature [K]; 1 at and above melt.
    double homologousTemperature(double temperatureK) const noexcept {
        const double t = (temperatureK - roomTemperature) / (meltTemperature - roomTemperature);
        return std::clamp(t, 0.0, 1.0);
    }

    /// T* straight from e [MJ/kg]: T* = e / (c_v (T_melt - T_room)), clamped to [0, 1].
    double homologousFromEnergy(double specificEnergy) const noexcept {
        return homologousTemperature(temperature(specificEnergy));
    }
};

} // namespace hvi::material
