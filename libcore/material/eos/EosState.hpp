// The result every equation of state returns at one point, and the one batch loop they share.
//
// Units (hydrocode system, docs/conventions.md): density g/cm^3, specific internal energy
// MJ/kg, pressure GPa, sound speed km/s. These are consistent: 1 g/cm^3 * 1 (km/s)^2 = 1 GPa
// and 1 (km/s)^2 = 1 MJ/kg, so no factor appears in any EOS formula.
//
// Why a template batch loop rather than a virtual EOS base: the solver picks the EOS once per
// body (std::visit on MaterialSpec::eos) and then runs this loop, which the compiler inlines
// for the concrete model; no call per particle goes through a table.
#pragma once

#include "core/Lanes.hpp"

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

namespace hvi::material {

/// Pressure [GPa] and squared adiabatic sound speed [(km/s)^2] at one point, or at four for
/// L = Lanes4 (core/Lanes.hpp: the same arithmetic in each lane).
template <class L>
struct EosStateOf {
    L pressure = 0.0;
    L soundSpeedSquared = 0.0;
};
using EosState = EosStateOf<double>;

/// One analytic form of an EOS at a point: P and its partial derivatives, from which the
/// isentropic sound speed follows.
template <class L>
struct EosBranchOf {
    L p;      ///< [GPa]
    L dPdRho; ///< at constant e [(km/s)^2]
    L dPdE;   ///< at constant rho [g/cm^3]

    /// The state, with c^2 = (dP/drho)_e + (P / rho^2) (dP/de)_rho floored at `floor2`
    /// (a NaN c^2 fails the comparison and stays NaN: bad input is not hidden).
    EosStateOf<L> state(L rho, double floor2) const noexcept {
        const L c2 = dPdRho + p * dPdE / (rho * rho);
        return {p, selectLess(c2, L(floor2), L(floor2), c2)};
    }
};
using EosBranch = EosBranchOf<double>;

/// Tillotson's rule between the incipient and complete vaporisation energies (GA-3216, 1962):
/// for e in (E_iv, E_cv), P linear in e between the `solid` and `expanded` forms, so P is
/// continuous in e; outside, the one form or the other.
inline EosBranch vaporisationBlend(const EosBranch& solid, const EosBranch& expanded, double e,
                                   double incipient, double complete) noexcept {
    if (e <= incipient) {
        return solid;
    }
    if (e >= complete) {
        return expanded;
    }
    const double width = complete - incipient;
    const double w = (e - incipient) / width;
    return {w * expanded.p + (1.0 - w) * solid.p, w * expanded.dPdRho + (1.0 - w) * solid.dPdRho,
            w * expanded.dPdE + (1.0 - w) * solid.dPdE + (expanded.p - solid.p) / width};
}

/// Evaluates `eos.evaluate(rho, e)` for every point: density [g/cm^3] and specific internal
/// energy [MJ/kg] in, pressure [GPa] and c^2 [(km/s)^2] out. All spans must have one length;
/// throws std::invalid_argument otherwise (checked once per call, not per point).
template <class Eos>
void evaluateEos(const Eos& eos, std::span<const double> density,
                 std::span<const double> specificEnergy, std::span<double> pressure,
                 std::span<double> soundSpeedSquared) {
    const std::size_t n = density.size();
    if (specificEnergy.size() != n || pressure.size() != n || soundSpeedSquared.size() != n) {
        throw std::invalid_argument("evaluateEos: spans differ in length (density " +
                                    std::to_string(n) + ", energy " +
                                    std::to_string(specificEnergy.size()) + ", pressure " +
                                    std::to_string(pressure.size()) + ", c^2 " +
                                    std::to_string(soundSpeedSquared.size()) + ")");
    }
    for (std::size_t i = 0; i < n; ++i) {
        const EosState s = eos.evaluate(density[i], specificEnergy[i]);
        pressure[i] = s.pressure;
        soundSpeedSquared[i] = s.soundSpeedSquared;
    }
}

} // namespace hvi::material
