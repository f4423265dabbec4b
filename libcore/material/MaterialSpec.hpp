// One material as the solver sees it: the parameter structs of its chosen EOS, strength,
// failure and thermal models, in hydrocode units (mm, us, mg: GPa, g/cm^3, MJ/kg, 1/us).
//
// The models are held in std::variant so the solver chooses once per body, outside the
// particle loop:
//   std::visit([&](const auto& eos) { evaluateEos(eos, rho, e, p, c2); }, spec.eos);
// and never dispatches per particle. A strengthless material (fluid, ideal gas) holds
// NoStrength and the solver allocates no deviatoric stress for it (hasStrength()).
#pragma once

#include "material/Temperature.hpp"
#include "material/eos/IdealGas.hpp"
#include "material/eos/MieGruneisen.hpp"
#include "material/eos/Tillotson.hpp"
#include "material/failure/JohnsonCookDamage.hpp"
#include "material/failure/SpallStrength.hpp"
#include "material/strength/JohnsonCook.hpp"

#include <optional>
#include <string>
#include <variant>

namespace hvi::material {

/// Hydrodynamic material: pressure only, no deviatoric stress.
struct NoStrength {};
/// Material that never fails.
struct NoFailure {};

using EquationOfState = std::variant<MieGruneisen, Tillotson, IdealGas>;
using StrengthModel = std::variant<NoStrength, JohnsonCookStrength>;
using FailureModel = std::variant<NoFailure, JohnsonCookDamage>;

struct MaterialSpec {
    std::string name;
    std::string description;
    /// Density of undisturbed material [g/cm^3]: the EOS reference density, used to set up
    /// bodies.
    double referenceDensity = 0.0;
    EquationOfState eos;
    StrengthModel strength;
    FailureModel failure;
    /// Shear modulus G [GPa]; > 0 whenever hasStrength(), else 0.
    double shearModulus = 0.0;
    /// Tensile (spall) failure beside the failure model; applied to points with strength.
    std::optional<SpallStrength> spall;
    /// Present whenever hasStrength() (JC thermal softening needs T*); optional otherwise.
    std::optional<ThermalParams> thermal;
    /// The material's JSON entry as read (with its source strings), for run provenance.
    std::string definitionJson;

    bool hasStrength() const noexcept { return !std::holds_alternative<NoStrength>(strength); }
    bool hasFailure() const noexcept { return !std::holds_alternative<NoFailure>(failure); }
};

} // namespace hvi::material
