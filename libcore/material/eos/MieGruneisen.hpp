// Mie-Grueneisen equation of state referenced to a linear Us-up shock Hugoniot.
//
// Reference: D.J. Steinberg, "Equation of State and Strength Properties of Selected
// Materials", LLNL UCRL-MA-106439 (1991; Change 1, 1996), Grueneisen form with S2 = S3 = 0;
// the same form is LS-DYNA's *EOS_GRUNEISEN. Material constants live in
// data/hydro_materials.json with their sources.
//
// Form used (cite this, not a paraphrase). With mu = rho/rho0 - 1 and e the specific
// internal energy:
//   compression, mu >= 0:
//     P = rho0 c0^2 mu [1 + (1 - Gamma0/2) mu - (b/2) mu^2] / [1 - (s - 1) mu]^2
//         + (Gamma0 + b mu) rho0 e
//   expansion, mu < 0:
//     P = rho0 c0^2 mu + (Gamma0 + b mu) rho0 e
// Why this form: it is exactly the Hugoniot-referenced form P = P_H + rho Gamma (e - e_H)
// with rho Gamma = rho0 (Gamma0 + b mu), P_H = rho0 c0^2 mu (1 + mu) / [1 - (s-1) mu]^2 (from
// Us = c0 + s up and the Rankine-Hugoniot jump conditions) and e_H = P_H mu / (2 rho0 (1+mu)).
// So every state on the Hugoniot gets P = rho0 Us up exactly; the unit test checks that.
// The same rho Gamma is used in expansion so that dP/de is continuous through mu = 0; with
// b = 0 (the Al 6061-T6 default) the expansion branch is P = rho0 c0^2 mu + Gamma0 rho0 e.
//
// Hot expanded states (optional, `expansion`). Below rho0 the form above keeps the thermal
// pressure at Gamma0 rho0 e whatever the density, so hot debris expanded to half its density
// still has the pressure of hot solid (about 230 GPa at 50 MJ/kg for aluminium) and a sound
// speed near 27 km/s. With `expansion` given, states with rho < rho0 and e above the
// incipient-vaporisation energy E_iv follow Tillotson's expanded branch instead (Tillotson,
// GA-3216, 1962; form as in Melosh, Impact Cratering, 1989, App. II), written on this EOS's
// own cold and thermal terms, with x = rho0/rho - 1:
//     P_e = a rho e + [(rho Gamma - a rho) e + f(mu) exp(-beta x)] exp(-alpha x^2)
// where f(mu) = rho0 c0^2 mu is the cold term above and rho Gamma = rho0 (Gamma0 + b mu). So
// P_e = P at rho0, and far from it the material tends to a gas of Grueneisen parameter a
// (P = a rho e, zero at zero density). Between E_iv and the complete-vaporisation energy E_cv
// P is linear in e between the two forms, as in Tillotson's EOS (P continuous in rho and e).
// a, alpha, beta, E_iv and E_cv are Tillotson's published constants of the metal.
//
// Sound speed: c^2 = (dP/drho)_e + (P / rho^2) (dP/de)_rho, the isentropic derivative.
//
// Guards (both documented limits of the model, not physics):
// * Compression cap. The Hugoniot denominator 1 - (s-1) mu vanishes at mu = 1/(s-1)
//   (rho = 3.5 rho0 for s = 1.4). Beyond the point where it falls to kMinHugoniotDenominator
//   the cold term continues along its tangent, so P stays finite, continuous and C1 and c^2
//   stays constant. For Al (s = 1.4) the cap is at mu = 2 (~3.8 TPa), far above the ~0.6 that
//   a 7 km/s Al-on-Al impact reaches; a linear Us-up fit is not valid there anyway.
// * Sound-speed floor. In tension the Grueneisen term makes (dP/drho)_s negative once
//   mu falls below about -0.27 at e = 0 for Al 6061-T6 (P ~ -20 GPa, ten times its spall
//   strength: material that should have failed long before);
//   c^2 is floored at (soundSpeedFloorFraction * c0)^2 so that time-step and artificial
//   viscosity estimates stay positive and finite. Solids add 4G/(3 rho) for the longitudinal
//   wave speed on top of this, which the solver does, so the floor mostly matters for fluids
//   and failed material.
//
// Units: rho g/cm^3, e MJ/kg, c0 km/s, P GPa, c^2 (km/s)^2 (see EosState.hpp).
// Precondition: rho > 0 (rho = 0 divides by zero in P/rho^2); NaN inputs propagate.
#pragma once

#include "material/eos/EosState.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

namespace hvi::material {

/// Tillotson's expanded-branch constants for MieGruneisen (see the file comment).
struct TillotsonExpansion {
    double gasGamma = 0.0;             ///< a: the Grueneisen parameter at zero density [-]
    double alpha = 0.0;                ///< decay of the solid's thermal and cold terms [-]
    double beta = 0.0;                 ///< further decay of the cold term [-]
    double incipientVaporEnergy = 0.0; ///< E_iv [MJ/kg]
    double completeVaporEnergy = 0.0;  ///< E_cv [MJ/kg], > E_iv
    bool enabled() const noexcept { return completeVaporEnergy > incipientVaporEnergy; }
};

struct MieGruneisen {
    static constexpr std::string_view kId = "eos.mie_gruneisen";
    /// Smallest Hugoniot denominator 1 - (s-1) mu evaluated; beyond it the cold curve is
    /// continued linearly (see the file comment).
    static constexpr double kMinHugoniotDenominator = 0.2;
    /// Default floor on the sound speed as a fraction of c0 (see the file comment).
    static constexpr double kDefaultSoundSpeedFloorFraction = 0.1;

    double referenceDensity = 0.0; ///< rho0 [g/cm^3]
    double bulkSoundSpeed = 0.0;   ///< c0, intercept of the Us-up fit [km/s]
    double hugoniotSlope = 0.0;    ///< s, slope of the Us-up fit [-]
    double gruneisenGamma = 0.0;   ///< Gamma0 at rho0 [-]
    double volumeCorrection = 0.0; ///< b, first-order volume correction to Gamma [-]
    double soundSpeedFloorFraction = kDefaultSoundSpeedFloorFraction; ///< c >= this * c0
    TillotsonExpansion expansion{}; ///< hot expanded states; off when not enabled()

    /// Whether the EOS describes expanded hot states (then the solver's density cut-off takes
    /// only tension away, not the pressure of hot expanded material).
    bool describesExpandedStates() const noexcept { return expansion.enabled(); }

    /// Pressure and c^2 at density rho [g/cm^3] and specific internal energy e [MJ/kg].
    EosState evaluate(double rho, double e) const noexcept {
        const double rho0 = referenceDensity;
        const double mu = rho / rho0 - 1.0;
        const EosBranch solid = solidBranch(e, mu);
        const double cFloor = soundSpeedFloorFraction * bulkSoundSpeed;
        if (mu < 0.0 && expansion.enabled() && e > expansion.incipientVaporEnergy) {
            return vaporisationBlend(solid, expandedBranch(rho, e, mu), e,
                                     expansion.incipientVaporEnergy, expansion.completeVaporEnergy)
                .state(rho, cFloor * cFloor);
        }
        return solid.state(rho, cFloor * cFloor);
    }

    /// The same without the expanded states, for L = double or Lanes4 (four points at once):
    /// evaluate() wherever describesExpandedStates() is false, to the last bit, since both
    /// run the one solidBranch.
    template <class L>
    EosStateOf<L> evaluateSolid(L rho, L e) const noexcept {
        const L mu = rho / referenceDensity - 1.0;
        const double cFloor = soundSpeedFloorFraction * bulkSoundSpeed;
        return solidBranch(e, mu).state(rho, cFloor * cFloor);
    }

    /// Pressure only [GPa].
    double pressure(double rho, double e) const noexcept { return evaluate(rho, e).pressure; }

private:
    /// The Hugoniot form, written once for a lane type: the compression and the cap are
    /// selected lane by lane (a lane in expansion computes the compressed terms and drops them).
    template <class L>
    EosBranchOf<L> solidBranch(L e, L mu) const noexcept {
        const double rho0 = referenceDensity;
        const double k = rho0 * bulkSoundSpeed * bulkSoundSpeed; // rho0 c0^2 [GPa]
        const double g0 = gruneisenGamma;
        const double b = volumeCorrection;

        // Cold (e-independent) part f(mu) and its derivative df/dmu.
        L cold = k * mu;
        L dColdDmu = k;
        if (anyLess(L(0.0), mu)) {
            const double sm1 = hugoniotSlope - 1.0;
            const double muCap = sm1 > 0.0 ? (1.0 - kMinHugoniotDenominator) / sm1 : 0.0;
            // Capped where sm1 > 0 and 1 - sm1 mu < kMinHugoniotDenominator (never for sm1 <= 0).
            const double noCap = -std::numeric_limits<double>::infinity();
            const L denominator = 1.0 - sm1 * mu;
            const L limit = L(sm1 > 0.0 ? kMinHugoniotDenominator : noCap);
            const L muEval = selectLess(denominator, limit, L(muCap), mu);
            const L d = 1.0 - sm1 * muEval;
            const L n = 1.0 + (1.0 - 0.5 * g0) * muEval - 0.5 * b * muEval * muEval;
            const L dn = (1.0 - 0.5 * g0) - b * muEval;
            const L d2 = d * d;
            const L compressedCold = k * muEval * n / d2;
            const L compressedSlope =
                k * ((n + muEval * dn) / d2 + 2.0 * sm1 * muEval * n / (d2 * d));
            const L cappedCold = compressedCold + compressedSlope * (mu - muEval);
            cold = selectLess(L(0.0), mu, selectLess(denominator, limit, cappedCold, compressedCold),
                              cold);
            dColdDmu = selectLess(L(0.0), mu, compressedSlope, dColdDmu);
        }

        const L rhoGamma = rho0 * (g0 + b * mu); // rho Gamma(rho) = (dP/de)_rho
        // (dP/drho)_e = (df/dmu + rho0 b e) / rho0, since dmu/drho = 1/rho0.
        return {cold + rhoGamma * e, (dColdDmu + rho0 * b * e) / rho0, rhoGamma};
    }

    /// Tillotson's expanded form on this EOS's terms (mu < 0, so the cold term is k mu).
    EosBranch expandedBranch(double rho, double e, double mu) const noexcept {
        const double rho0 = referenceDensity;
        const double k = rho0 * bulkSoundSpeed * bulkSoundSpeed;
        const double a = expansion.gasGamma;
        const double x = rho0 / rho - 1.0;
        const double dxDrho = -rho0 / (rho * rho);
        const double expAlpha = std::exp(-expansion.alpha * x * x);
        const double expBeta = std::exp(-expansion.beta * x);
        const double rhoGamma = rho0 * (gruneisenGamma + volumeCorrection * mu);
        const double cold = k * mu * expBeta;
        const double bracket = (rhoGamma - a * rho) * e + cold;
        const double dBracketDrho =
            (volumeCorrection - a) * e + k * expBeta / rho0 - expansion.beta * cold * dxDrho;
        return {a * rho * e + bracket * expAlpha,
                a * e + (dBracketDrho - 2.0 * expansion.alpha * x * dxDrho * bracket) * expAlpha,
                a * rho + (rhoGamma - a * rho) * expAlpha};
    }
};

} // namespace hvi::material
