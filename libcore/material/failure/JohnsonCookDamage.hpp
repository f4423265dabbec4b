// Johnson-Cook cumulative damage and fracture strain.
//
// Reference: G.R. Johnson and W.H. Cook, "Fracture characteristics of three metals subjected
// to various strains, strain rates, temperatures and pressures", Eng. Fract. Mech. 21 (1985)
// 31-48:
//   eps_f = [D1 + D2 exp(D3 sigma*)] [1 + D4 ln eps_dot*] [1 + D5 T*]
//   D     = sum d eps_p / eps_f,  failure at D >= 1
// sigma* = sigma_mean / sigma_eq = -P / sigma_eq (tension positive). With D3 < 0 (-0.47 for
// Al 6061-T6 in the source study) eps_f falls as triaxiality rises. Sign pitfall
// (hydrocode-notes.md section 4.3): Spheral writes exp(D3 P / sigma_eq), i.e. the opposite
// sign of sigma*; constants must not be moved between codes without checking which is used.
// eps_dot* is floored at 1 and T* clamped to [0, 1], as in JohnsonCookStrength.
//
// Three documented limits (model choices, not from the 1985 paper):
// * No damage accumulates below the compression cut-off triaxiality, default -1/3: Bao and
//   Wierzbicki, "On the cut-off value of negative triaxiality for fracture", Eng. Fract.
//   Mech. 72 (2005) 1049-1069, found no fracture below sigma* = -1/3 in upsetting tests of
//   2024-T351, and many codes adopt the cut-off. Without it, shock-compressed material
//   (sigma* -> the lower clamp) accumulates damage that the Taylor rods recovered whole do not
//   show.
// * sigma* is clamped to [minTriaxiality, maxTriaxiality], default [-1.5, 1.5] as in
//   Uintah's JohnsonCookDamage. Above: a pure hydrostatic state has sigma_eq = 0 and
//   sigma* = +-inf; a material whose fit was calibrated to a lower triaxiality sets
//   maxTriaxiality there, so eps_f is held at its last calibrated value and near-hydrostatic
//   tension is left to the spall criterion (SpallStrength.hpp) instead of an extrapolated
//   fit. Below: in a strong shock sigma* reaches -100s and exp(D3 sigma*) overflows.
// * eps_f is floored at minFailureStrain, default 0.01. The Al 6061-T6 fit turns negative
//   above sigma* = ln(-D1/D2)/D3 = 1.347 (spall triaxialities reach that), and a negative or
//   zero eps_f would make D run backwards or divide by zero. 0.01 is below every value the fit
//   gives inside its calibrated range (0.136 at sigma* = 1) and above the elastic strain at
//   yield (Y/3G ~ 0.0035), so a point must flow plastically before it can fail.
//
// Optional, for reversed plastic flow (docs/notebook/spall-and-damage.md: a wall cycled by
// in-plane waves), the two parts of the cyclic void growth model of Kanvinde and Deierlein,
// J. Eng. Mech. 133 (2007) 701-712, in Johnson-Cook form:
// * compressionClosure c in [0, 1], default 0: below the cut-off, plastic flow closes damage
//   instead of leaving it, D -= c d eps_p / eps_f(|sigma*|), floored at 0; failed material
//   (D >= 1) stays failed. c = 1 is that model's void shrinkage under compression at the
//   mirrored rate of growth.
// * cyclicDegradation lambda >= 0, default 0: failure comes at D >= exp(-lambda eps_p,0), with
//   eps_p,0 the plastic strain at the start of the current tensile excursion (the plastic
//   strain before the first increment above the cut-off that follows one below it; 0 when
//   the point has never flowed below the cut-off). That model's degradation of the critical
//   void growth index with the plastic strain accumulated before each tensile cycle; lambda
//   is a material constant fitted to cyclic tests (unknown for 6061-T6, an input).
// A monotonic path never flows below the cut-off, so both reduce to Johnson-Cook there. The
// per-point state is the damage D and tensionOnset (eps_p,0, or kCompressiveFlow while the
// last plastic increment was below the cut-off).
//
// Failed material (D >= 1) carries no deviatoric stress and no tension: applyFailedState
// zeroes S and floors the pressure at 0. It keeps its mass, momentum and compressive
// response (the "retain inertia" convention, hydrocode-notes.md section 3).
//
// Units: P, sigma_eq in GPa; strain rates in 1/us (reference 1/s = 1e-6 /us).
#pragma once

#include "material/strength/StressDeviator.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace hvi::material {

struct JohnsonCookDamage {
    static constexpr std::string_view kId = "failure.johnson_cook";
    static constexpr double kDefaultReferenceStrainRatePerUs = 1.0e-6;
    static constexpr double kDefaultMinTriaxiality = -1.5;
    static constexpr double kDefaultMaxTriaxiality = 1.5;
    static constexpr double kDefaultMinFailureStrain = 0.01;
    static constexpr double kDefaultCompressionCutoff = -1.0 / 3.0;

    double d1 = 0.0;
    double d2 = 0.0;
    double d3 = 0.0;
    double d4 = 0.0;
    double d5 = 0.0;
    double referenceStrainRatePerUs = kDefaultReferenceStrainRatePerUs; ///< [1/us]
    double minTriaxiality = kDefaultMinTriaxiality;
    double maxTriaxiality = kDefaultMaxTriaxiality;
    double minFailureStrain = kDefaultMinFailureStrain;   ///< > 0
    double compressionCutoff = kDefaultCompressionCutoff; ///< no damage below this sigma*
    double compressionClosure = 0.0; ///< in [0, 1]: damage closed below the cut-off
    double cyclicDegradation = 0.0;  ///< lambda >= 0: critical D = exp(-lambda eps_p,0)

    /// tensionOnset while the point's last plastic increment was below the cut-off: the next
    /// increment above it starts a tensile excursion.
    static constexpr double kCompressiveFlow = -1.0;

    /// sigma* = -P / sigma_eq, clamped to [minTriaxiality, maxTriaxiality]. sigma_eq = 0
    /// gives the bound on the side of the mean stress (0 when P = 0 too).
    double triaxiality(double pressure, double vonMises) const noexcept {
        const double meanStress = -pressure;
        if (vonMises == 0.0) {
            return meanStress > 0.0 ? maxTriaxiality : (meanStress < 0.0 ? minTriaxiality : 0.0);
        }
        return std::clamp(meanStress / vonMises, minTriaxiality, maxTriaxiality);
    }

    /// eps_f at clamped triaxiality sigma*, equivalent strain rate [1/us] and T* in [0, 1];
    /// never below minFailureStrain.
    double failureStrain(double triaxialityValue, double strainRatePerUs,
                         double homologousTemperature) const noexcept {
        const double sStar = std::clamp(triaxialityValue, minTriaxiality, maxTriaxiality);
        const double ratio = strainRatePerUs / referenceStrainRatePerUs;
        const double rateTerm = ratio <= 1.0 ? 1.0 : 1.0 + d4 * std::log(ratio);
        const double tStar = std::clamp(homologousTemperature, 0.0, 1.0);
        const double epsF = (d1 + d2 * std::exp(d3 * sStar)) * rateTerm * (1.0 + d5 * tStar);
        return epsF < minFailureStrain ? minFailureStrain : epsF;
    }

    /// D + d eps_p / eps_f, capped at 1.
    static double accumulate(double damage, double plasticStrainIncrement,
                             double failureStrainValue) noexcept {
        const double d = damage + plasticStrainIncrement / failureStrainValue;
        return d > 1.0 ? 1.0 : d;
    }

    /// The damage after a plastic strain increment d eps_p (from plasticStrainBefore) at
    /// pressure P and von Mises stress sigma_eq [GPa]. Below the compression cut-off: D is
    /// unchanged, or closed by compressionClosure at the mirrored rate (failed material stays
    /// failed), and tensionOnset becomes kCompressiveFlow. Above it: accumulate(), a new
    /// tensile excursion recorded in tensionOnset if the last flow was compressive, and D set
    /// to 1 once it reaches the critical value exp(-cyclicDegradation eps_p,0).
    double damageAfter(double damage, double& tensionOnset, double plasticStrainBefore,
                       double plasticStrainIncrement, double pressure, double vonMises,
                       double strainRatePerUs, double homologousTemperature) const noexcept {
        const double sStar = triaxiality(pressure, vonMises);
        if (sStar < compressionCutoff) {
            tensionOnset = kCompressiveFlow;
            if (compressionClosure <= 0.0 || damage >= 1.0) {
                return damage;
            }
            const double mirrored = failureStrain(-sStar, strainRatePerUs, homologousTemperature);
            const double d = damage - compressionClosure * plasticStrainIncrement / mirrored;
            return d < 0.0 ? 0.0 : d;
        }
        if (tensionOnset < 0.0) {
            tensionOnset = plasticStrainBefore;
        }
        const double d = accumulate(damage, plasticStrainIncrement,
                                    failureStrain(sStar, strainRatePerUs, homologousTemperature));
        return d >= criticalDamage(tensionOnset) ? 1.0 : d;
    }

    /// The damage at which a tensile excursion that began at plastic strain eps_p,0 fails.
    double criticalDamage(double tensionOnsetStrain) const noexcept {
        return cyclicDegradation > 0.0 ? std::exp(-cyclicDegradation * tensionOnsetStrain) : 1.0;
    }

    /// Failed material (D >= 1): no deviatoric stress, no tension (P floored at 0).
    static void applyFailedState(double damage, StressDeviator& s, double& pressure) noexcept {
        if (damage >= 1.0) {
            s = StressDeviator{};
            pressure = pressure < 0.0 ? 0.0 : pressure;
        }
    }
};

} // namespace hvi::material
