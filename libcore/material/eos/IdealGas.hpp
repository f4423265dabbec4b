// Gamma-law ideal gas, for the verification problems (Sod, Noh, Sedov) that have exact
// solutions.
//
// P = (gamma - 1) rho e,   c^2 = gamma P / rho = gamma (gamma - 1) e.
// (Any gas-dynamics text, e.g. Toro, "Riemann Solvers and Numerical Methods for Fluid
// Dynamics", 3rd ed. 2009, section 1.2.)
//
// Units: rho g/cm^3, e MJ/kg, P GPa, c^2 (km/s)^2 (see EosState.hpp).
// c^2 is floored at 0 for e < 0, which a gas cannot physically reach; e = 0 (the cold gas of
// Noh's problem) correctly has c = 0, so no positive floor is imposed here.
#pragma once

#include "material/eos/EosState.hpp"

#include <string_view>

namespace hvi::material {

struct IdealGas {
    static constexpr std::string_view kId = "eos.ideal_gas";

    double gamma = 5.0 / 3.0; ///< ratio of specific heats [-], > 1

    /// A gas is an expanded state: the solver's density cut-off takes no pressure from it.
    static constexpr bool describesExpandedStates() noexcept { return true; }

    EosState evaluate(double rho, double e) const noexcept {
        const double p = (gamma - 1.0) * rho * e;
        const double c2 = gamma * (gamma - 1.0) * e;
        return {p, c2 < 0.0 ? 0.0 : c2};
    }

    double pressure(double rho, double e) const noexcept { return evaluate(rho, e).pressure; }
};

} // namespace hvi::material
