// Reading the material library: strict checks with every problem reported at once, then
// conversion from file units (MPa, J/(kg K), 1/s) to hydrocode units (GPa, MJ/(kg K), 1/us).
//
// The checks are written out here rather than in a JSON Schema because several are
// cross-field (E_cv > E_iv, T_melt > T_room, strength needs elastic and thermal) and the
// messages should name the physical quantity and its unit.
#include "material/MaterialLibrary.hpp"

#include "core/Error.hpp"
#include "core/Units.hpp"
#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"
#include "io/Resources.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

namespace hvi::material {

namespace {

using nlohmann::json;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// RFC 6901 escaping of one reference token.
std::string pointerToken(const std::string& key) {
    std::string out;
    for (char c : key) {
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
    return out;
}

std::string formatNumber(double v) {
    std::ostringstream out;
    out.precision(10);
    out << v;
    return out.str();
}

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const auto& item : items) {
        text += (text.empty() ? "" : ", ") + item;
    }
    return text;
}

/// A lower bound on a number: none, > value, or >= value.
struct Lower {
    enum class Kind { None, Above, AtLeast } kind = Kind::None;
    double value = 0.0;
};
constexpr Lower above(double v) {
    return {Lower::Kind::Above, v};
}
constexpr Lower atLeast(double v) {
    return {Lower::Kind::AtLeast, v};
}

/// One JSON object being read. It records which keys were read, so that everything else can
/// be reported as unknown, and adds every problem to the shared issue list instead of
/// throwing, so that one run reports them all.
class Section {
public:
    Section(const json& node, std::string pointer, const std::string& file,
            std::vector<InputIssue>& issues, const std::string& what)
        : m_node(node), m_pointer(std::move(pointer)), m_file(file), m_issues(issues) {
        if (!node.is_object()) {
            issue(m_pointer, std::string("must be an object, got ") + node.type_name(), what);
            m_valid = false;
        }
    }

    bool valid() const { return m_valid; }
    const std::string& pointer() const { return m_pointer; }
    std::string pointerTo(const std::string& key) const {
        return m_pointer + "/" + pointerToken(key);
    }

    void issue(const std::string& pointer, const std::string& problem,
               const std::string& expected) {
        m_issues.push_back({m_file, pointer, problem, expected});
    }

    /// The child node `key` (marked as read), or nullptr if absent.
    const json* child(const std::string& key) {
        m_read.insert(key);
        if (!m_valid) {
            return nullptr;
        }
        auto it = m_node.find(key);
        return it == m_node.end() ? nullptr : &*it;
    }

    /// A number; NaN (and an issue) when missing, not a number or out of bounds. A fallback
    /// makes the key optional.
    double number(const std::string& key, const std::string& what, Lower lower = {},
                  std::optional<double> fallback = std::nullopt) {
        const json* node = child(key);
        if (!m_valid) {
            return kNaN;
        }
        if (node == nullptr) {
            if (fallback) {
                return *fallback;
            }
            issue(pointerTo(key), "missing", what);
            return kNaN;
        }
        if (!node->is_number()) {
            issue(pointerTo(key), std::string("must be a number, got ") + node->type_name(), what);
            return kNaN;
        }
        const double v = node->get<double>();
        const bool ok = lower.kind == Lower::Kind::None ||
                        (lower.kind == Lower::Kind::Above && v > lower.value) ||
                        (lower.kind == Lower::Kind::AtLeast && v >= lower.value);
        if (!std::isfinite(v) || !ok) {
            const char* op = lower.kind == Lower::Kind::Above ? "> " : ">= ";
            issue(pointerTo(key),
                  std::string("must be ") + op + formatNumber(lower.value) + ", got " +
                      formatNumber(v),
                  what);
            return kNaN;
        }
        return v;
    }

    /// A non-empty string; "" (and an issue) when missing or not a non-empty string.
    std::string text(const std::string& key, const std::string& what) {
        const json* node = child(key);
        if (!m_valid) {
            return {};
        }
        if (node == nullptr) {
            issue(pointerTo(key), "missing", what);
            return {};
        }
        if (!node->is_string() || node->get<std::string>().empty()) {
            issue(pointerTo(key),
                  node->is_string() ? std::string("must not be empty")
                                    : std::string("must be a string, got ") + node->type_name(),
                  what);
            return {};
        }
        return node->get<std::string>();
    }

    /// Reads the sub-object `key` with `read(Section&)` when present (an issue if it is not
    /// an object); returns whether the key was present.
    template <class Read>
    bool readSection(const std::string& key, const std::string& what, Read&& read) {
        const json* node = child(key);
        if (node == nullptr) {
            return false;
        }
        Section sub(*node, pointerTo(key), m_file, m_issues, what);
        if (sub.valid()) {
            read(sub);
        }
        return true;
    }

    /// Reports every key that was not read.
    void rejectUnknownKeys() {
        if (!m_valid) {
            return;
        }
        for (auto it = m_node.begin(); it != m_node.end(); ++it) {
            if (m_read.count(it.key()) == 0) {
                std::vector<std::string> known(m_read.begin(), m_read.end());
                issue(pointerTo(it.key()), "unknown key '" + it.key() + "'",
                      "one of: " + joined(known));
            }
        }
    }

private:
    const json& m_node;
    std::string m_pointer;
    const std::string& m_file;
    std::vector<InputIssue>& m_issues;
    std::set<std::string> m_read;
    bool m_valid = true;
};

constexpr const char* kSourceWhat = "citation for the values in this block";

/// The "type" of a model block, checked against the accepted names; "" when invalid.
std::string modelType(Section& s, const std::vector<std::string>& accepted) {
    const std::string what = "model type, one of: " + joined(accepted);
    const std::string type = s.text("type", what);
    if (type.empty()) {
        return {};
    }
    if (std::find(accepted.begin(), accepted.end(), type) == accepted.end()) {
        s.issue(s.pointerTo("type"), "unknown type '" + type + "'", what);
        return {};
    }
    return type;
}

/// Tillotson's incipient and complete vaporisation energies [MJ/kg], E_cv > E_iv.
void readVaporEnergies(Section& s, double& incipient, double& complete) {
    incipient =
        s.number("E_iv_MJ_kg", "incipient vaporisation energy E_iv [MJ/kg], > 0", above(0.0));
    complete =
        s.number("E_cv_MJ_kg", "complete vaporisation energy E_cv [MJ/kg], > E_iv", above(0.0));
    if (complete <= incipient) {
        s.issue(s.pointerTo("E_cv_MJ_kg"),
                "must exceed E_iv_MJ_kg (" + formatNumber(incipient) + "), got " +
                    formatNumber(complete),
                "complete vaporisation energy E_cv [MJ/kg], > E_iv");
    }
}

/// Tillotson's expanded-branch constants of a Mie-Grueneisen EOS (MieGruneisen.hpp).
TillotsonExpansion readExpansion(Section& s) {
    s.text("source", kSourceWhat);
    TillotsonExpansion x;
    x.gasGamma =
        s.number("a", "Tillotson a (Grueneisen parameter of the gas) [-], > 0", above(0.0));
    x.alpha = s.number("alpha", "Tillotson alpha [-], >= 0", atLeast(0.0));
    x.beta = s.number("beta", "Tillotson beta [-], >= 0", atLeast(0.0));
    readVaporEnergies(s, x.incipientVaporEnergy, x.completeVaporEnergy);
    s.rejectUnknownKeys();
    return x;
}

std::optional<EquationOfState> readEos(Section& s, double& referenceDensity) {
    const std::string type = modelType(s, {"mie_gruneisen", "tillotson", "ideal_gas"});
    if (type.empty()) {
        return std::nullopt; // other keys depend on the type: nothing more to check
    }
    s.text("source", kSourceWhat);
    std::optional<EquationOfState> eos;
    referenceDensity =
        s.number("reference_density_g_cm3", "reference density rho0 [g/cm^3], > 0", above(0.0));
    if (type == "mie_gruneisen") {
        MieGruneisen m;
        m.referenceDensity = referenceDensity;
        m.bulkSoundSpeed = s.number("c0_km_s", "bulk sound speed c0 [km/s], > 0", above(0.0));
        m.hugoniotSlope = s.number("s", "Us-up slope s [-], > 0", above(0.0));
        m.gruneisenGamma = s.number("gamma0", "Grueneisen gamma0 [-], >= 0", atLeast(0.0));
        m.volumeCorrection =
            s.number("b", "first-order volume correction b [-] (default 0)", {}, 0.0);
        s.readSection("expansion", "Tillotson expanded-state constants object (optional)",
                      [&](Section& x) { m.expansion = readExpansion(x); });
        eos = m;
    } else if (type == "tillotson") {
        Tillotson t;
        t.referenceDensity = referenceDensity;
        t.bulkModulusA = s.number("A_GPa", "Tillotson A [GPa], > 0", above(0.0));
        t.nonlinearModulusB = s.number("B_GPa", "Tillotson B [GPa], >= 0", atLeast(0.0));
        t.referenceEnergy = s.number("E0_MJ_kg", "Tillotson E0 [MJ/kg], > 0", above(0.0));
        readVaporEnergies(s, t.incipientVaporEnergy, t.completeVaporEnergy);
        t.smallA = s.number("a", "Tillotson a [-], >= 0", atLeast(0.0));
        t.smallB = s.number("b", "Tillotson b [-], >= 0", atLeast(0.0));
        t.alpha = s.number("alpha", "Tillotson alpha [-], >= 0", atLeast(0.0));
        t.beta = s.number("beta", "Tillotson beta [-], >= 0", atLeast(0.0));
        eos = t;
    } else {
        IdealGas g;
        g.gamma = s.number("gamma", "ratio of specific heats gamma [-], > 1", above(1.0));
        eos = g;
    }
    s.rejectUnknownKeys();
    return eos;
}

double readShearModulus(Section& s) {
    s.text("source", kSourceWhat);
    const double g = s.number("shear_modulus_GPa", "shear modulus G [GPa], > 0", above(0.0));
    s.rejectUnknownKeys();
    return g;
}

ThermalParams readThermal(Section& s) {
    s.text("source", kSourceWhat);
    ThermalParams t;
    t.specificHeat = units::jPerKgKToMjPerKgK(
        s.number("specific_heat_J_kgK", "specific heat [J/(kg K)], > 0", above(0.0)));
    t.roomTemperature =
        s.number("room_temperature_K", "room (reference) temperature [K], > 0", above(0.0));
    t.meltTemperature =
        s.number("melt_temperature_K", "melt temperature [K], > room_temperature_K", above(0.0));
    if (t.meltTemperature <= t.roomTemperature) {
        s.issue(s.pointerTo("melt_temperature_K"),
                "must exceed room_temperature_K (" + formatNumber(t.roomTemperature) + "), got " +
                    formatNumber(t.meltTemperature),
                "melt temperature [K], > room_temperature_K");
    }
    s.rejectUnknownKeys();
    return t;
}

double readReferenceRate(Section& s) {
    return units::perSecondToPerMicrosecond(
        s.number("reference_strain_rate_per_s",
                 "Johnson-Cook reference strain rate [1/s], > 0 (default 1)", above(0.0), 1.0));
}

std::optional<JohnsonCookStrength> readStrength(Section& s) {
    if (modelType(s, {"johnson_cook"}).empty()) {
        return std::nullopt;
    }
    s.text("source", kSourceWhat);
    JohnsonCookStrength jc;
    jc.yieldStress =
        units::mpaToGpa(s.number("A_MPa", "JC yield stress A [MPa], >= 0", atLeast(0.0)));
    jc.hardeningModulus =
        units::mpaToGpa(s.number("B_MPa", "JC hardening modulus B [MPa], >= 0", atLeast(0.0)));
    jc.hardeningExponent = s.number("n", "JC hardening exponent n [-], >= 0", atLeast(0.0));
    jc.strainRateCoefficient =
        s.number("C", "JC strain-rate coefficient C [-], >= 0", atLeast(0.0));
    jc.thermalExponent = s.number("m", "JC thermal-softening exponent m [-], > 0", above(0.0));
    jc.referenceStrainRatePerUs = readReferenceRate(s);
    s.rejectUnknownKeys();
    return jc;
}

std::optional<JohnsonCookDamage> readFailure(Section& s) {
    if (modelType(s, {"johnson_cook"}).empty()) {
        return std::nullopt;
    }
    s.text("source", kSourceWhat);
    JohnsonCookDamage d;
    d.d1 = s.number("D1", "JC failure constant D1 [-]");
    d.d2 = s.number("D2", "JC failure constant D2 [-]");
    d.d3 = s.number("D3", "JC failure constant D3 [-] (exp(D3 sigma*), sigma* tension positive)");
    d.d4 = s.number("D4", "JC failure constant D4 [-]");
    d.d5 = s.number("D5", "JC failure constant D5 [-]");
    d.referenceStrainRatePerUs = readReferenceRate(s);
    d.minTriaxiality = s.number("triaxiality_min", "lower clamp of sigma* [-] (default -1.5)", {},
                                JohnsonCookDamage::kDefaultMinTriaxiality);
    d.maxTriaxiality =
        s.number("triaxiality_max", "upper clamp of sigma* [-], > triaxiality_min (default 1.5)",
                 {}, JohnsonCookDamage::kDefaultMaxTriaxiality);
    d.minFailureStrain = s.number("min_failure_strain", "floor of eps_f [-], > 0 (default 0.01)",
                                  above(0.0), JohnsonCookDamage::kDefaultMinFailureStrain);
    d.compressionCutoff =
        s.number("compression_cutoff_triaxiality",
                 "sigma* below which no damage accumulates [-] (default -1/3, Bao-Wierzbicki)", {},
                 JohnsonCookDamage::kDefaultCompressionCutoff);
    d.compressionClosure = s.number(
        "compression_closure",
        "fraction in [0, 1] of the mirrored tensile rate at which plastic flow below the cut-off "
        "closes damage [-] (default 0: none; 1: Kanvinde-Deierlein cyclic void growth)",
        atLeast(0.0), 0.0);
    d.cyclicDegradation = s.number(
        "cyclic_degradation",
        "lambda >= 0 of the critical damage exp(-lambda eps_p,0), eps_p,0 the plastic strain at "
        "the start of the tensile excursion [-] (default 0: none; Kanvinde-Deierlein)",
        atLeast(0.0), 0.0);
    if (d.compressionClosure > 1.0) {
        s.issue(s.pointerTo("compression_closure"),
                "must be at most 1, got " + formatNumber(d.compressionClosure),
                "fraction in [0, 1]");
    }
    if (d.maxTriaxiality <= d.minTriaxiality) {
        s.issue(s.pointerTo("triaxiality_max"),
                "must exceed triaxiality_min (" + formatNumber(d.minTriaxiality) + "), got " +
                    formatNumber(d.maxTriaxiality),
                "upper clamp of sigma* [-], > triaxiality_min");
    }
    s.rejectUnknownKeys();
    return d;
}

SpallStrength readSpall(Section& s) {
    s.text("source", kSourceWhat);
    SpallStrength spall;
    spall.strengthGPa =
        s.number("strength_GPa", "spall strength: mean tension at failure [GPa], > 0", above(0.0));
    spall.rateExponent = s.number(
        "rate_exponent", "power-law rate exponent n [-], >= 0 (default 0)", atLeast(0.0), 0.0);
    spall.referenceStrainRatePerUs = units::perSecondToPerMicrosecond(
        s.number("reference_strain_rate_per_s",
                 "strain rate of strength_GPa [1/s], > 0 (default 1)", above(0.0), 1.0));
    s.readSection("tuler_butcher", "cumulative-damage (Tuler-Butcher) object", [&](Section& tb) {
        CumulativeSpall c;
        c.thresholdGPa = tb.number("threshold_GPa",
                                   "tension sigma_0 beyond which damage accumulates [GPa], >= 0 "
                                   "and below strength_GPa",
                                   atLeast(0.0));
        c.exponent =
            tb.number("exponent", "lambda of (sigma_1 - sigma_0)^lambda [-], >= 1", atLeast(1.0));
        c.criticalIntegral =
            tb.number("critical_integral_GPa_us",
                      "K_f: the integral that fails a point [GPa^exponent us], > 0", above(0.0));
        tb.text("source", kSourceWhat);
        tb.rejectUnknownKeys();
        if (c.thresholdGPa >= spall.strengthGPa) {
            tb.issue(tb.pointerTo("threshold_GPa"), "is not below strength_GPa",
                     "a threshold below the instantaneous strength, its ceiling");
        }
        spall.cumulative = c;
    });
    s.rejectUnknownKeys();
    return spall;
}

/// Reads one material entry into `spec`; problems go to `issues`.
void readMaterial(const json& entry, const std::string& name, const std::string& pointer,
                  const std::string& file, std::vector<InputIssue>& issues, MaterialSpec& spec) {
    Section m(entry, pointer, file, issues, "material definition object");
    if (!m.valid()) {
        return;
    }
    spec.name = name;
    spec.description = m.text("description", "one-line description of the material");
    spec.definitionJson = io::jsonText(entry);

    const bool hasEos = m.readSection("eos", "equation-of-state object", [&](Section& s) {
        if (auto eos = readEos(s, spec.referenceDensity)) {
            spec.eos = *eos;
        }
    });
    const bool hasElastic = m.readSection("elastic", "elastic-constants object", [&](Section& s) {
        spec.shearModulus = readShearModulus(s);
    });
    const bool hasThermal = m.readSection("thermal", "thermal-constants object",
                                          [&](Section& s) { spec.thermal = readThermal(s); });
    const bool hasStrength = m.readSection("strength", "strength-model object", [&](Section& s) {
        if (auto jc = readStrength(s)) {
            spec.strength = *jc;
        }
    });
    const bool hasFailure = m.readSection("failure", "failure-model object", [&](Section& s) {
        if (auto d = readFailure(s)) {
            spec.failure = *d;
        }
    });

    const bool hasSpall = m.readSection("spall", "spall-strength object",
                                        [&](Section& s) { spec.spall = readSpall(s); });

    if (!hasEos) {
        m.issue(m.pointerTo("eos"), "missing", "equation-of-state object");
    }
    if (hasSpall && !hasStrength) {
        m.issue(m.pointerTo("strength"), "missing (required with a spall strength)",
                "strength-model object: spall fails points of a solid");
    }
    // A strength model needs G for the elastic update and T_room/T_melt for T*; failure
    // accumulates the plastic strain that only a strength model produces.
    if (hasStrength && !hasElastic) {
        m.issue(m.pointerTo("elastic"), "missing (required with a strength model)",
                "elastic-constants object with shear_modulus_GPa");
    }
    if (hasStrength && !hasThermal) {
        m.issue(m.pointerTo("thermal"), "missing (required with a strength model)",
                "thermal-constants object (specific heat, room and melt temperature)");
    }
    if (hasFailure && !hasStrength) {
        m.issue(m.pointerTo("strength"), "missing (required with a failure model)",
                "strength-model object: failure accumulates plastic strain");
    }
    m.rejectUnknownKeys();
}

} // namespace

const MaterialLibrary& MaterialLibrary::builtin() {
    static const MaterialLibrary library = [] {
        const std::string key = "data/hydro_materials.json";
        return fromJson(json::parse(resources::get(key)), "<builtin>/" + key);
    }();
    return library;
}

namespace {

/// The "patches" of a user library: each a JSON merge patch (RFC 7386) of the material of
/// that name in `base`, read as a whole material once applied.
void readPatches(const json& patches, const MaterialLibrary* base, const std::string& label,
                 std::vector<InputIssue>& issues, std::map<std::string, MaterialSpec>& out) {
    const std::string what =
        "object mapping names of built-in materials to JSON merge patches (RFC 7386) of them";
    if (!patches.is_object() || patches.empty()) {
        issues.push_back({label, "/patches",
                          patches.is_object()
                              ? std::string("must patch at least one material")
                              : std::string("must be an object, got ") + patches.type_name(),
                          what});
        return;
    }
    for (auto it = patches.begin(); it != patches.end(); ++it) {
        const std::string pointer = "/patches/" + pointerToken(it.key());
        if (base == nullptr || !base->contains(it.key())) {
            issues.push_back({label, pointer, "no material '" + it.key() + "' to patch",
                              base ? "one of: " + joined(base->names())
                                   : std::string("a library laid over the built-in one")});
            continue;
        }
        if (!it.value().is_object()) {
            issues.push_back({label, pointer,
                              std::string("must be an object, got ") + it.value().type_name(),
                              what});
            continue;
        }
        json entry = json::parse(base->get(it.key()).definitionJson);
        entry.merge_patch(it.value());
        MaterialSpec spec;
        readMaterial(entry, it.key(), pointer, label, issues, spec);
        out.insert_or_assign(it.key(), std::move(spec));
    }
}

} // namespace

MaterialLibrary MaterialLibrary::fromJson(const json& document, const std::string& label,
                                          const MaterialLibrary* base) {
    std::vector<InputIssue> issues;
    MaterialLibrary library;
    library.m_label = label;

    Section top(document, "", label, issues, "material library object");
    if (top.valid()) {
        if (const json* description = top.child("description");
            description != nullptr && !description->is_string()) {
            top.issue("/description",
                      std::string("must be a string, got ") + description->type_name(),
                      "description of the library");
        }
        const json* patches = top.child("patches");
        if (patches != nullptr) {
            readPatches(*patches, base, label, issues, library.m_materials);
        }
        const json* materials = top.child("materials");
        if (materials == nullptr) {
            if (patches == nullptr) {
                top.issue("/materials", "missing", "object mapping material names to definitions");
            }
        } else if (!materials->is_object() || materials->empty()) {
            top.issue("/materials",
                      materials->is_object()
                          ? std::string("must define at least one material")
                          : std::string("must be an object, got ") + materials->type_name(),
                      "object mapping material names to definitions");
        } else {
            for (auto it = materials->begin(); it != materials->end(); ++it) {
                MaterialSpec spec;
                readMaterial(it.value(), it.key(), "/materials/" + pointerToken(it.key()), label,
                             issues, spec);
                library.m_materials.emplace(it.key(), std::move(spec));
            }
        }
        top.rejectUnknownKeys();
    }
    if (!issues.empty()) {
        throw InputError(std::move(issues));
    }
    return library;
}

MaterialLibrary MaterialLibrary::fromFile(const std::string& path, const MaterialLibrary* base) {
    // The shared reader: one linear pre-scan (nesting, non-finite numbers) before parsing.
    return fromJson(io::readJsonFile(path), path, base);
}

const MaterialSpec& MaterialLibrary::get(const std::string& name) const {
    auto it = m_materials.find(name);
    if (it == m_materials.end()) {
        throw InputError(m_label, "", "unknown material '" + name + "'",
                         "one of: " + joined(names()));
    }
    return it->second;
}

std::vector<std::string> MaterialLibrary::names() const {
    std::vector<std::string> out;
    out.reserve(m_materials.size());
    for (const auto& [name, spec] : m_materials) {
        out.push_back(name);
    }
    return out;
}

void MaterialLibrary::merge(const MaterialLibrary& other) {
    for (const auto& [name, spec] : other.m_materials) {
        m_materials.insert_or_assign(name, spec);
    }
}

} // namespace hvi::material
