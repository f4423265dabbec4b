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
// The principal stress, not the mean tension, because that is what the datum measures: in a
// plate-impact test (uniaxial strain) the free-surface velocity pulls back by du after its
// peak, and 0.5 rho0 c du estimates the longitudinal stress at which the spall plane opened
// (Kanel's acoustic approximation; tests/verification/SpallPlate_test.cpp uses the longitudinal
// sound speed). That stress exceeds the mean tension by 2/3 of the yield stress of material
// yielding in tension.
//
// Units: GPa; strain rates in 1/us.
#pragma once

#include "material/strength/StressDeviator.hpp"

#include <cmath>
#include <string_view>

namespace hvi::material {

struct SpallStrength {
    static constexpr std::string_view kId = "failure.spall_strength";

    double strengthGPa = 0.0;           ///< sigma_sp0 > 0
    double rateExponent = 0.0;          ///< n >= 0 (0: rate-independent)
    double referenceStrainRatePerUs = 1.0e-6; ///< eps_dot_0 [1/us]

    /// sigma_sp at the given strain rate [1/us].
    double strengthAt(double strainRatePerUs) const noexcept {
        if (rateExponent == 0.0 || !(strainRatePerUs > referenceStrainRatePerUs)) {
            return strengthGPa;
        }
        return strengthGPa * std::pow(strainRatePerUs / referenceStrainRatePerUs, rateExponent);
    }

    /// True when the largest principal stress (tension positive) of pressure P and deviator
    /// S exceeds the spall strength.
    bool exceeded(const StressDeviator& s, double pressure, double strainRatePerUs) const noexcept {
        return s.maxPrincipal() - pressure > strengthAt(strainRatePerUs);
    }
};

} // namespace hvi::material
