// Johnson-Cook flow stress.
//
// Reference: G.R. Johnson and W.H. Cook, "A constitutive model and data for metals subjected
// to large strains, high strain rates and high temperatures", Proc. 7th Int. Symp. on
// Ballistics, The Hague, 1983, pp. 541-547:
//   Y = (A + B eps_p^n) (1 + C ln eps_dot*) (1 - T*^m)
// eps_p   equivalent plastic strain (clamped at >= 0),
// eps_dot* = eps_dot / eps_dot_0, floored at 1 so the rate term never softens below the
//          quasi-static curve (ln of a ratio < 1 is negative and, for small rates, unbounded),
// T*      homologous temperature in [0, 1] (ThermalParams::homologousTemperature), so Y = 0 at
//          and above melt.
//
// Units: A, B, Y in GPa (JSON carries MPa). Strain rates in 1/us, the hydrocode's time unit:
// the reference rate eps_dot_0 = 1/s of the JC fits is 1e-6 /us. Mixing the two would shift
// the rate term by C ln(1e6) = 0.15 (15 % of Y for Al 6061-T6, C = 0.011), a silent error, so
// the field carries its unit in its name.
#pragma once

#include <cmath>
#include <string_view>

namespace hvi::material {

struct JohnsonCookStrength {
    static constexpr std::string_view kId = "strength.johnson_cook";
    /// eps_dot_0 = 1/s expressed in 1/us.
    static constexpr double kDefaultReferenceStrainRatePerUs = 1.0e-6;

    double yieldStress = 0.0;                                           ///< A [GPa]
    double hardeningModulus = 0.0;                                      ///< B [GPa]
    double hardeningExponent = 0.0;                                     ///< n [-]
    double strainRateCoefficient = 0.0;                                 ///< C [-]
    double thermalExponent = 1.0;                                       ///< m [-]
    double referenceStrainRatePerUs = kDefaultReferenceStrainRatePerUs; ///< eps_dot_0 [1/us]

    /// Strain-hardening factor A + B eps_p^n [GPa].
    double hardening(double plasticStrain) const noexcept {
        // Written so that NaN reaches pow and propagates instead of reading as eps_p = 0.
        return plasticStrain <= 0.0
                   ? yieldStress
                   : yieldStress + hardeningModulus * std::pow(plasticStrain, hardeningExponent);
    }

    /// Rate factor 1 + C ln(max(eps_dot / eps_dot_0, 1)); eps_dot in 1/us.
    double rateFactor(double strainRatePerUs) const noexcept {
        const double ratio = strainRatePerUs / referenceStrainRatePerUs;
        return ratio <= 1.0 ? 1.0 : 1.0 + strainRateCoefficient * std::log(ratio);
    }

    /// Thermal factor 1 - T*^m with T* clamped to [0, 1].
    double thermalFactor(double homologousTemperature) const noexcept {
        if (homologousTemperature <= 0.0) {
            return 1.0;
        }
        if (homologousTemperature >= 1.0) {
            return 0.0;
        }
        return 1.0 - std::pow(homologousTemperature, thermalExponent);
    }

    /// A flow stress [GPa] that flowStress() does not fall below at this T* for any plastic
    /// strain >= 0 and strain rate >= 0: A (1 - T*) where B >= 0, C >= 0 and m >= 1 (then the
    /// hardening is at least A, the rate factor at least 1, and T*^m <= T*; each holds for
    /// the rounded factors too, since rounding is monotonic), otherwise 0 (no bound). A point
    /// whose von Mises stress stays under it is elastic without the powers and the logarithm
    /// the flow stress costs.
    double flowStressFloor(double homologousTemperature) const noexcept {
        if (!(yieldStress > 0.0 && hardeningModulus >= 0.0 && strainRateCoefficient >= 0.0 &&
              thermalExponent >= 1.0 && homologousTemperature < 1.0)) {
            return 0.0; // a NaN T* too
        }
        return yieldStress * (1.0 - std::max(homologousTemperature, 0.0));
    }

    /// Flow stress Y [GPa] at equivalent plastic strain, equivalent strain rate [1/us] and T*.
    double flowStress(double plasticStrain, double strainRatePerUs,
                      double homologousTemperature) const noexcept {
        return hardening(plasticStrain) * rateFactor(strainRatePerUs) *
               thermalFactor(homologousTemperature);
    }
};

} // namespace hvi::material
