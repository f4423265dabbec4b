// The hydrocode material library: named MaterialSpecs read from JSON.
//
// The built-in library is data/hydro_materials.json, compiled in (io/Resources.hpp). A user
// file with the same schema can add materials or replace built-in ones (merge()).
//
// Schema (units in the keys; converted to hydrocode units on reading):
//   { "description": "...",
//     "materials": { "<name>": {
//         "description": "...",                                   required
//         "eos": { "type": "mie_gruneisen" | "tillotson" | "ideal_gas", ..., "source": "..." },
//         "elastic":  { "shear_modulus_GPa", "source" },            required with strength
//         "thermal":  { "specific_heat_J_kgK", "room_temperature_K", "melt_temperature_K",
//                       "source" },                                 required with strength
//         "strength": { "type": "johnson_cook", "A_MPa", "B_MPa", "n", "C", "m",
//                       "reference_strain_rate_per_s" (default 1), "source" },   optional
//         "failure":  { "type": "johnson_cook", "D1".."D5", "reference_strain_rate_per_s",
//                       "triaxiality_min", "triaxiality_max", "min_failure_strain",
//                       "compression_cutoff_triaxiality", "compression_closure",
//                       "cyclic_degradation" (defaults in JohnsonCookDamage.hpp),
//                       "source" }                              optional, needs strength
//         "spall":    { "strength_GPa", "rate_exponent" (default 0),
//                       "reference_strain_rate_per_s" (default 1), "source" }  optional,
//                                                                   needs strength
//   } } }
// EOS keys: mie_gruneisen: reference_density_g_cm3, c0_km_s, s, gamma0, b (default 0),
// expansion (optional: a, alpha, beta, E_iv_MJ_kg, E_cv_MJ_kg, source; MieGruneisen.hpp);
// tillotson: reference_density_g_cm3, A_GPa, B_GPa, E0_MJ_kg, E_iv_MJ_kg, E_cv_MJ_kg, a, b,
// alpha, beta; ideal_gas: gamma, reference_density_g_cm3.
// A user library may instead (or as well) give "patches": { "<name>": {...} }, each a JSON
// merge patch (RFC 7386) of the material of that name in the library it is laid over: the
// blocks and keys it gives replace the base's, null removes one, the rest is kept. So a
// sensitivity study changes one constant without copying the material.
// Every block needs a non-empty "source" citing its values. Unknown keys, missing keys, wrong
// types and non-physical values are all reported together in one hvi::InputError, each
// located by JSON pointer (e.g. "/materials/Al6061-T6/eos/c0_km_s: must be > 0, got -1").
#pragma once

#include "material/MaterialSpec.hpp"

#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace hvi::material {

class MaterialLibrary {
public:
    /// The compiled-in library (data/hydro_materials.json), parsed on first use.
    static const MaterialLibrary& builtin();

    /// A library from a parsed document with the schema above. `label` names the source in
    /// error messages (a file name, or e.g. "<builtin>"). Throws hvi::InputError listing every
    /// problem found. `base` is the library the result will be laid over, which its
    /// "patches" change (none allowed without it).
    static MaterialLibrary fromJson(const nlohmann::json& document, const std::string& label,
                                    const MaterialLibrary* base = nullptr);

    /// A library from a JSON file; throws hvi::InputError if it cannot be read or parsed, or
    /// fails the checks of fromJson.
    static MaterialLibrary fromFile(const std::string& path, const MaterialLibrary* base = nullptr);

    /// The material called `name`; throws hvi::InputError naming it and listing the known
    /// names when there is none.
    const MaterialSpec& get(const std::string& name) const;

    bool contains(const std::string& name) const { return m_materials.count(name) != 0; }

    /// Known names, sorted.
    std::vector<std::string> names() const;

    /// Adds the materials of `other`, replacing any of the same name (a user library laid
    /// over the built-in one).
    void merge(const MaterialLibrary& other);

    /// Where the library came from (the label given to fromJson / the file path).
    const std::string& label() const { return m_label; }

private:
    std::string m_label;
    std::map<std::string, MaterialSpec> m_materials;
};

} // namespace hvi::material
