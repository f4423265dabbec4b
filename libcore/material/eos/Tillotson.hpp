// Tillotson equation of state for metals at hypervelocity-impact pressures.
//
// References: J.H. Tillotson, "Metallic equations of state for hypervelocity impact",
// General Atomic report GA-3216 (1962); H.J. Melosh, "Impact Cratering: A Geologic Process"
// (Oxford, 1989), Appendix II, which gives the form used here and the aluminium constants in
// data/hydro_materials.json.
//
// With eta = rho/rho0, mu = eta - 1, omega = 1 + e / (E0 eta^2):
//   compressed or cold expanded (rho >= rho0, or e <= E_iv):
//     P_c = (a + b/omega) rho e + A mu + B mu^2
//   hot expanded (rho < rho0 and e >= E_cv), with x = rho0/rho - 1:
//     P_e = a rho e + [b rho e / omega + A mu exp(-beta x)] exp(-alpha x^2)
//   in between (rho < rho0, E_iv < e < E_cv), linear in e between the two:
//     P = [(e - E_iv) P_e + (E_cv - e) P_c] / (E_cv - E_iv)
// The blend keeps P continuous across E_iv and E_cv; P_c = P_e at rho = rho0, so P is
// continuous across rho0 as well.
//
// Sound speed: c^2 = (dP/drho)_e + (P / rho^2)(dP/de)_rho, with the derivatives of each
// branch taken analytically (the test checks them against finite differences along an
// isentrope). In expansion c^2 can turn negative; it is floored at
// (soundSpeedFloorFraction * c0)^2 with c0 = sqrt(A / rho0), the same rule as MieGruneisen.
//
// Not included: the cold-expansion pressure cutoff some codes add (miluphcuda's rho_limit,
// P = 0 below 0.9 rho0 when cold). That is a fracture model in disguise; here the failure
// model decides when material stops carrying tension.
//
// Units: rho g/cm^3, e and E0, E_iv, E_cv MJ/kg, A and B GPa, P GPa, c^2 (km/s)^2.
// Preconditions: rho > 0 and e > -E0 (rho/rho0)^2 (else omega <= 0; internal energy that
// negative is not a state the model describes).
#pragma once

#include "material/eos/EosState.hpp"

#include <cmath>
#include <string_view>

namespace hvi::material {

struct Tillotson {
    static constexpr std::string_view kId = "eos.tillotson";
    static constexpr double kDefaultSoundSpeedFloorFraction = 0.1;

    double referenceDensity = 0.0;     ///< rho0 [g/cm^3]
    double bulkModulusA = 0.0;         ///< A [GPa]
    double nonlinearModulusB = 0.0;    ///< B [GPa]
    double referenceEnergy = 0.0;      ///< E0 [MJ/kg]
    double incipientVaporEnergy = 0.0; ///< E_iv [MJ/kg]
    double completeVaporEnergy = 0.0;  ///< E_cv [MJ/kg], > E_iv
    double smallA = 0.0;               ///< a [-]
    double smallB = 0.0;               ///< b [-]
    double alpha = 0.0;                ///< alpha [-]
    double beta = 0.0;                 ///< beta [-]
    double soundSpeedFloorFraction = kDefaultSoundSpeedFloorFraction;

    /// Tillotson's EOS describes hot expanded states (the solver's density cut-off takes only
    /// tension away).
    static constexpr bool describesExpandedStates() noexcept { return true; }

    EosState evaluate(double rho, double e) const noexcept {
        const double rho0 = referenceDensity;
        const double eta = rho / rho0;
        const double mu = eta - 1.0;
        const double omega = 1.0 + e / (referenceEnergy * eta * eta);
        const double dOmegaDrho = -2.0 * e / (referenceEnergy * eta * eta * eta * rho0);
        const double dOmegaDe = 1.0 / (referenceEnergy * eta * eta);

        const EosBranch compressed = compressedBranch(rho, e, mu, omega, dOmegaDrho, dOmegaDe);
        const EosBranch b =
            mu < 0.0 && e > incipientVaporEnergy
                ? vaporisationBlend(compressed,
                                    expandedBranch(rho, e, eta, mu, omega, dOmegaDrho, dOmegaDe), e,
                                    incipientVaporEnergy, completeVaporEnergy)
                : compressed;
        return b.state(rho,
                       soundSpeedFloorFraction * soundSpeedFloorFraction * bulkModulusA / rho0);
    }

    double pressure(double rho, double e) const noexcept { return evaluate(rho, e).pressure; }

private:
    EosBranch compressedBranch(double rho, double e, double mu, double omega, double dOmegaDrho,
                               double dOmegaDe) const noexcept {
        const double rho0 = referenceDensity;
        const double coef = smallA + smallB / omega;
        const double bRhoEOverOmega2 = smallB * rho * e / (omega * omega);
        return {coef * rho * e + bulkModulusA * mu + nonlinearModulusB * mu * mu,
                coef * e - bRhoEOverOmega2 * dOmegaDrho +
                    (bulkModulusA + 2.0 * nonlinearModulusB * mu) / rho0,
                coef * rho - bRhoEOverOmega2 * dOmegaDe};
    }

    EosBranch expandedBranch(double rho, double e, double eta, double mu, double omega,
                             double dOmegaDrho, double dOmegaDe) const noexcept {
        const double rho0 = referenceDensity;
        const double x = 1.0 / eta - 1.0;
        const double dxDrho = -1.0 / (eta * eta * rho0);
        const double expAlpha = std::exp(-alpha * x * x);
        const double expBeta = std::exp(-beta * x);
        const double thermal = smallB * rho * e / omega;
        const double cold = bulkModulusA * mu * expBeta;
        const double bracket = thermal + cold;
        const double bRhoEOverOmega2 = smallB * rho * e / (omega * omega);
        const double dBracketDrho = smallB * e / omega - bRhoEOverOmega2 * dOmegaDrho +
                                    bulkModulusA * expBeta / rho0 - beta * cold * dxDrho;
        return {smallA * rho * e + bracket * expAlpha,
                smallA * e + (dBracketDrho - 2.0 * alpha * x * dxDrho * bracket) * expAlpha,
                smallA * rho + (smallB * rho / omega - bRhoEOverOmega2 * dOmegaDe) * expAlpha};
    }
};

} // namespace hvi::material
