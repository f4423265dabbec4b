// Spall: failure of a material point in tension beyond the material's spall strength.
//
// A point fails (damage set to 1) when its largest principal stress (tension positive),
// sigma_1 = -P + the largest principal value of the deviator, exceeds sigma_sp, optionally
// rate-dependent:
//   sigma_sp(eps_dot) = sigma_sp0 max(1, eps_dot / eps_dot_0)^n
// the power law aluminium spall strengths follow over plate-impact strain rates (exponent about
// 0.06 for aluminium, Kanel, Razorenov et al.; notes section 3 of the axis-failure notes). It
// plays the part of the "pressure cutoff" or "hydro tensile limit" of other codes (a spall
// model beside Johnson-Cook damage, as Radioss pairs /FAIL/SPALLING with /FAIL/JOHNSON; those
// cut off the mean tension, this one the principal stress, see below): Johnson-Cook's fit
// describes ductile failure over the triaxialities it was calibrated at, and is not
// extrapolated to the near-hydrostatic tension of a spall plane.
//
// Optionally also cumulative (Tuler and Butcher, Int. J. Fract. Mech. 4 (1968) 431): real spall
// takes time (voids nucleate, grow and join), so a short tensile excursion beyond a threshold
// sigma_0 fails a point only once
//   K = integral of (sigma_1 - sigma_0)^lambda dt
// reaches K_f. Its damage K / K_f adds to the point's damage (with Johnson-Cook's), and the
// instantaneous strength stays as the ceiling no duration can exceed. No measured constants of
// these alloys were read (docs/materials.md); the criterion is an input for sensitivity studies.
//
// The principal stress, not the mean tension, because that is what the datum measures: in a
// plate-impact test (uniaxial strain) the free-surface velocity pulls back by du after its
// peak, and 0.5 rho0 c du estimates the longitudinal stress at which the spall plane opened
// (Kanel's acoustic approximation; tests/verification/SpallPlate_test.cpp uses the longitudinal
// sound speed). That stress exceeds the mean tension by 2/3 of the yield stress of material
// yielding in tension. The estimate is not the input, though: once the strength exceeds the
// release's elastic range the spall signal overtakes the slower plastic part of the release
// and the estimate reads low, so a measured pull-back value is matched by simulating its
// experiment (docs/materials.md, spall strength).
//
// Units: GPa; strain rates in 1/us.
#pragma once

#include "material/strength/StressDeviator.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

namespace hvi::material {

/// The cumulative part: damage rate (sigma_1 - sigma_0)^lambda / K_f beyond sigma_0.
struct CumulativeSpall {
    double thresholdGPa = 0.0;     ///< sigma_0 >= 0
    double exponent = 2.0;         ///< lambda >= 1
    double criticalIntegral = 0.0; ///< K_f [GPa^lambda us], > 0

    /// dD/dt [1/us] at principal tension sigma_1 [GPa].
    double damageRate(double sigma1) const noexcept {
        const double excess = sigma1 - thresholdGPa;
        return excess > 0.0 ? std::pow(excess, exponent) / criticalIntegral : 0.0;
    }
};

struct SpallStrength {
    static constexpr std::string_view kId = "failure.spall_strength";

    double strengthGPa = 0.0;                  ///< sigma_sp0 > 0
    double rateExponent = 0.0;                 ///< n >= 0 (0: rate-independent)
    double referenceStrainRatePerUs = 1.0e-6;  ///< eps_dot_0 [1/us]
    std::optional<CumulativeSpall> cumulative; ///< Tuler-Butcher damage below the ceiling

    /// sigma_sp at the given strain rate [1/us].
    double strengthAt(double strainRatePerUs) const noexcept {
        if (rateExponent == 0.0 || !(strainRatePerUs > referenceStrainRatePerUs)) {
            return strengthGPa;
        }
        return strengthGPa * std::pow(strainRatePerUs / referenceStrainRatePerUs, rateExponent);
    }

    /// The point's damage after a step of dt [us] at deviator S and pressure P: 1 beyond the
    /// strength, else `damage` plus the cumulative part's increment (capped at 1).
    double damageAfter(double damage, const StressDeviator& s, double pressure,
                       double strainRatePerUs, double dtUs) const noexcept {
        const double sigma1 = s.maxPrincipal() - pressure;
        if (sigma1 > strengthAt(strainRatePerUs)) {
            return 1.0;
        }
        if (!cumulative) {
            return damage;
        }
        return std::min(damage + dtUs * cumulative->damageRate(sigma1), 1.0);
    }
};

} // namespace hvi::material
