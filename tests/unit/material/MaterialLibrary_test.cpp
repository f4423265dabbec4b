// The material library: the built-in Al 6061-T6 entry against the source study's own data
// file (an independent copy of the constants), unit conversion on reading, and the errors a
// user gets for an unknown name or a bad file.
#include "TestPaths.hpp"
#include "Tolerance.hpp"
#include "core/Error.hpp"
#include "material/MaterialLibrary.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

using hvi::InputError;
using hvi::material::JohnsonCookDamage;
using hvi::material::JohnsonCookStrength;
using hvi::material::MaterialLibrary;
using hvi::material::MaterialSpec;
using hvi::material::MieGruneisen;
using hvi::test::near;

namespace {

nlohmann::json readJson(const std::filesystem::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

/// The message of the InputError that `f` throws ("" if it throws none).
template <class F>
std::string inputErrorMessage(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(MaterialLibrary, Al6061T6HasTheSourcedHydroConstants) {
    const MaterialSpec& al = MaterialLibrary::builtin().get("Al6061-T6");
    ASSERT_TRUE(std::holds_alternative<MieGruneisen>(al.eos));
    const auto& eos = std::get<MieGruneisen>(al.eos);
    // Steinberg 1996 values as written in the JSON: exact decimal round trips.
    EXPECT_EQ(eos.referenceDensity, 2.703);
    EXPECT_EQ(al.referenceDensity, 2.703);
    EXPECT_EQ(eos.bulkSoundSpeed, 5.24);
    EXPECT_EQ(eos.hugoniotSlope, 1.40);
    EXPECT_EQ(eos.gruneisenGamma, 1.97);
    EXPECT_EQ(eos.volumeCorrection, 0.0);
    EXPECT_EQ(al.shearModulus, 27.6);
    ASSERT_TRUE(al.thermal.has_value());
    // 885 J/(kg K) -> MJ/(kg K): one multiplication by 1e-6.
    EXPECT_TRUE(near("c_v", al.thermal->specificHeat, 885.0e-6, 0.0, 1e-15));
    EXPECT_TRUE(al.hasStrength());
    EXPECT_TRUE(al.hasFailure());
    EXPECT_FALSE(al.definitionJson.empty());
}

TEST(MaterialLibrary, Al6061T6JohnsonCookConstantsEqualTheSourceStudy) {
    // The validation file is the source study's own record; the library must agree with it
    // after the MPa -> GPa and 1/s -> 1/us conversions.
    const auto thesis =
        readJson(hvi::test::sharedPath("validation/thesis_cases.json"))["materials"]["Al6061-T6"];
    const auto& js = thesis["johnson_cook_strength"];
    const auto& jf = thesis["johnson_cook_failure"];
    const MaterialSpec& al = MaterialLibrary::builtin().get("Al6061-T6");

    const auto& jc = std::get<JohnsonCookStrength>(al.strength);
    // Conversions are one multiplication: 1e-15 relative.
    EXPECT_TRUE(near("A [GPa]", jc.yieldStress, js["A_MPa"].get<double>() * 1e-3, 0.0, 1e-15));
    EXPECT_TRUE(near("B [GPa]", jc.hardeningModulus, js["B_MPa"].get<double>() * 1e-3, 0.0, 1e-15));
    EXPECT_EQ(jc.hardeningExponent, js["n"].get<double>());
    EXPECT_EQ(jc.strainRateCoefficient, js["C"].get<double>());
    EXPECT_EQ(jc.thermalExponent, js["m"].get<double>());
    EXPECT_TRUE(near("reference rate [1/us]", jc.referenceStrainRatePerUs, 1.0e-6, 0.0, 1e-15));
    EXPECT_EQ(al.thermal->meltTemperature, js["T_melt_K"].get<double>());
    EXPECT_EQ(al.thermal->roomTemperature, js["T_room_K"].get<double>());

    const auto& d = std::get<JohnsonCookDamage>(al.failure);
    EXPECT_EQ(d.d1, jf["D1"].get<double>());
    EXPECT_EQ(d.d2, jf["D2"].get<double>());
    EXPECT_EQ(d.d3, jf["D3"].get<double>());
    EXPECT_EQ(d.d4, jf["D4"].get<double>());
    EXPECT_EQ(d.d5, jf["D5"].get<double>());
    EXPECT_LT(d.d3, 0.0); // the sign convention of JohnsonCookDamage.hpp
    EXPECT_GT(d.minFailureStrain, 0.0);
}

TEST(MaterialLibrary, EveryBuiltinMaterialLoads) {
    const auto names = MaterialLibrary::builtin().names();
    for (const char* expected :
         {"Al6061-T6", "Al6061-T6-Tillotson", "Al2017-T4", "Steel4340", "ideal_gas_5_3"}) {
        EXPECT_TRUE(MaterialLibrary::builtin().contains(expected)) << expected;
    }
    EXPECT_EQ(names.size(), 16u); // the five above and the eleven alloys of the NASA tests
    const MaterialSpec& gas = MaterialLibrary::builtin().get("ideal_gas_5_3");
    EXPECT_FALSE(gas.hasStrength());
    EXPECT_FALSE(gas.hasFailure());
    EXPECT_TRUE(
        near("gamma", std::get<hvi::material::IdealGas>(gas.eos).gamma, 5.0 / 3.0, 0.0, 1e-15));
    EXPECT_EQ(MaterialLibrary::builtin().get("Al2017-T4").referenceDensity, 2.80);
    EXPECT_TRUE(std::holds_alternative<hvi::material::Tillotson>(
        MaterialLibrary::builtin().get("Al6061-T6-Tillotson").eos));
}

TEST(MaterialLibrary, UnknownNameListsTheKnownOnes) {
    const std::string message =
        inputErrorMessage([] { MaterialLibrary::builtin().get("Al7049-T73"); });
    ASSERT_FALSE(message.empty()) << "no InputError thrown";
    EXPECT_NE(message.find("unknown material 'Al7049-T73'"), std::string::npos) << message;
    for (const auto& name : MaterialLibrary::builtin().names()) {
        EXPECT_NE(message.find(name), std::string::npos) << name << " missing from: " << message;
    }
}

TEST(MaterialLibrary, BadFieldsAreAllReportedByPointer) {
    const auto path = hvi::test::dataPath("material/bad_field.json");
    try {
        MaterialLibrary::fromFile(path.string());
        FAIL() << "bad_field.json was accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        // Every issue names the file and the JSON pointer of the offending field.
        EXPECT_NE(message.find(path.string() + ": /materials/MyAl/eos/c0_km_s: must be > 0, got "
                                               "-5.24"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("/materials/MyAl/eos/gama0: unknown key 'gama0'"), std::string::npos)
            << message;
        EXPECT_NE(message.find("/materials/MyAl/eos/gamma0: missing"), std::string::npos)
            << message;
        EXPECT_EQ(e.issues().size(), 3u) << message;
    }
}

TEST(MaterialLibrary, StrengthWithoutElasticOrThermalConstantsIsRejected) {
    const std::string message = inputErrorMessage([] {
        MaterialLibrary::fromFile(
            hvi::test::dataPath("material/strength_without_elastic.json").string());
    });
    EXPECT_NE(message.find("/materials/Soft/elastic: missing (required with a strength model)"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("/materials/Soft/thermal: missing"), std::string::npos) << message;
}

TEST(MaterialLibrary, FailureWithoutStrengthIsRejected) {
    nlohmann::json doc = readJson(hvi::test::dataPath("material/user_library.json"));
    doc["materials"]["MyAl"]["failure"] = {
        {"type", "johnson_cook"}, {"D1", 0.0}, {"D2", 1.0}, {"D3", -1.0}, {"D4", 0.0}, {"D5", 0.0},
        {"source", "test"}};
    const std::string message = inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "doc"); });
    EXPECT_NE(message.find("doc: /materials/MyAl/strength: missing (required with a failure "
                           "model)"),
              std::string::npos)
        << message;
}

TEST(MaterialLibrary, MissingSourceIsRejected) {
    nlohmann::json doc = readJson(hvi::test::dataPath("material/user_library.json"));
    doc["materials"]["MyAl"]["eos"].erase("source");
    const std::string message = inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "doc"); });
    EXPECT_NE(message.find("doc: /materials/MyAl/eos/source: missing"), std::string::npos)
        << message;
}

TEST(MaterialLibrary, UnreadableOrInvalidFilesAreInputErrors) {
    EXPECT_NE(inputErrorMessage([] {
                  MaterialLibrary::fromFile(hvi::test::dataPath("material/absent.json").string());
              }).find("cannot be read"),
              std::string::npos);
    const std::string message = inputErrorMessage(
        [] { MaterialLibrary::fromFile(hvi::test::dataPath("material/not_json.json").string()); });
    EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
    EXPECT_EQ(message.find("[json.exception"), std::string::npos) << message;
}

TEST(MaterialLibrary, UserLibraryLoadsAndMergesOverTheBuiltinOne) {
    const MaterialLibrary user =
        MaterialLibrary::fromFile(hvi::test::dataPath("material/user_library.json").string());
    const MaterialSpec& myAl = user.get("MyAl");
    EXPECT_FALSE(myAl.hasStrength());
    EXPECT_EQ(std::get<MieGruneisen>(myAl.eos).volumeCorrection, 0.48);

    MaterialLibrary merged = MaterialLibrary::builtin();
    merged.merge(user);
    EXPECT_TRUE(merged.contains("MyAl"));
    EXPECT_TRUE(merged.contains("Steel4340"));
    // The user's Al6061-T6 (hydrodynamic only) replaced the built-in one.
    EXPECT_FALSE(merged.get("Al6061-T6").hasStrength());
    EXPECT_TRUE(MaterialLibrary::builtin().get("Al6061-T6").hasStrength());
}

// A user library's "patches" change one block of a built-in material and keep the rest; the
// repository's expanded-states overlay patches every aluminium's EOS and nothing else.
TEST(MaterialLibrary, PatchesChangeOnlyWhatTheyGive) {
    const MaterialLibrary& builtin = MaterialLibrary::builtin();
    const auto path = hvi::test::sourcePath("workflows/materials/expanded-states.json");
    const MaterialLibrary patched = MaterialLibrary::fromFile(path.string(), &builtin);
    for (const std::string& name : patched.names()) {
        const MaterialSpec& after = patched.get(name);
        const MaterialSpec& before = builtin.get(name);
        const auto& eosAfter = std::get<MieGruneisen>(after.eos);
        const auto& eosBefore = std::get<MieGruneisen>(before.eos);
        EXPECT_TRUE(eosAfter.describesExpandedStates()) << name;
        EXPECT_FALSE(eosBefore.describesExpandedStates()) << name;
        EXPECT_EQ(eosAfter.expansion.gasGamma, 0.5) << name;
        EXPECT_EQ(eosAfter.expansion.completeVaporEnergy, 13.9) << name;
        EXPECT_EQ(eosAfter.bulkSoundSpeed, eosBefore.bulkSoundSpeed) << name;
        EXPECT_EQ(eosAfter.gruneisenGamma, eosBefore.gruneisenGamma) << name;
        EXPECT_EQ(after.hasStrength(), before.hasStrength()) << name;
        EXPECT_EQ(after.description, before.description) << name;
    }
    // Every Mie-Grueneisen aluminium of the built-in library is patched.
    for (const std::string& name : builtin.names()) {
        if (name.rfind("Al", 0) == 0 &&
            std::holds_alternative<MieGruneisen>(builtin.get(name).eos)) {
            EXPECT_TRUE(patched.contains(name)) << name;
        }
    }
}

// Every sensitivity overlay of the workflows (make -C workflows validate VARIANT=<name>) loads
// over the built-in library, and the fracture-rate overlay changes D4 of the alloys on the
// source study's 6061-T6 fit and nothing else of their failure model.
TEST(MaterialLibrary, WorkflowOverlaysLoad) {
    const MaterialLibrary& builtin = MaterialLibrary::builtin();
    std::size_t overlays = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(hvi::test::sourcePath("workflows/materials"))) {
        if (entry.path().extension() == ".json") {
            EXPECT_NO_THROW(MaterialLibrary::fromFile(entry.path().string(), &builtin))
                << entry.path();
            ++overlays;
        }
    }
    EXPECT_GE(overlays, 4u);
    const MaterialLibrary rate = MaterialLibrary::fromFile(
        hvi::test::sourcePath("workflows/materials/jc-rate-0.036.json").string(), &builtin);
    EXPECT_TRUE(rate.contains("Al6061-T6"));
    for (const std::string& name : rate.names()) {
        const auto& after = std::get<JohnsonCookDamage>(rate.get(name).failure);
        const auto& before = std::get<JohnsonCookDamage>(builtin.get(name).failure);
        EXPECT_EQ(before.d4, 0.0) << name;
        EXPECT_EQ(after.d4, 0.036) << name;
        EXPECT_EQ(after.d1, before.d1) << name;
        EXPECT_EQ(after.d3, before.d3) << name;
        EXPECT_EQ(after.maxTriaxiality, before.maxTriaxiality) << name;
        EXPECT_EQ(after.compressionClosure, before.compressionClosure) << name;
    }
}

TEST(MaterialLibrary, BadPatchesAreReportedByPointer) {
    const MaterialLibrary& builtin = MaterialLibrary::builtin();
    const nlohmann::json doc = nlohmann::json::parse(R"({"patches": {
        "NoSuchAl": {"eos": {"c0_km_s": 5.0}},
        "Al2024-T3": {"eos": {"expansion": {"a": 0.5, "alpha": 5, "beta": 5, "E_iv_MJ_kg": 3,
                                             "E_cv_MJ_kg": 2, "source": "test"}}},
        "Al7075-T6": 3}})");
    const std::string message =
        inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "patch.json", &builtin); });
    EXPECT_NE(message.find("patch.json: /patches/NoSuchAl: no material 'NoSuchAl' to patch"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("/patches/Al2024-T3/eos/expansion/E_cv_MJ_kg: must exceed E_iv_MJ_kg"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("/patches/Al7075-T6: must be an object, got number"), std::string::npos)
        << message;
    // Without a library to lay it over, a patch has nothing to change.
    const nlohmann::json alone = nlohmann::json::parse(R"({"patches": {"Al6061-T6": {}}})");
    EXPECT_NE(inputErrorMessage([&] {
                  MaterialLibrary::fromJson(alone, "alone.json");
              }).find("/patches/Al6061-T6: no material 'Al6061-T6' to patch"),
              std::string::npos);
}

// Every aluminium has a spall strength, read in GPa; the 6061-T6 fit's damage stops at
// sigma* = 1 and below the compression cut-off -1/3; every Johnson-Cook failure block closes
// damage under compressive flow, without degradation (data/hydro_materials.json).
TEST(MaterialLibrary, AluminiumSpallStrengthAndDamageRange) {
    for (const auto& name : MaterialLibrary::builtin().names()) {
        const MaterialSpec& m = MaterialLibrary::builtin().get(name);
        if (name.rfind("Al", 0) == 0) {
            ASSERT_TRUE(m.spall.has_value()) << name;
            EXPECT_EQ(m.spall->strengthGPa, 2.0) << name;
            EXPECT_EQ(m.spall->rateExponent, 0.0) << name;
        }
    }
    const auto& d =
        std::get<JohnsonCookDamage>(MaterialLibrary::builtin().get("Al6061-T6").failure);
    EXPECT_EQ(d.maxTriaxiality, 1.0);
    EXPECT_EQ(d.compressionCutoff, -1.0 / 3.0);
    for (const auto& name : MaterialLibrary::builtin().names()) {
        const auto* jc =
            std::get_if<JohnsonCookDamage>(&MaterialLibrary::builtin().get(name).failure);
        if (jc) {
            EXPECT_EQ(jc->compressionClosure, 1.0) << name;
            EXPECT_EQ(jc->cyclicDegradation, 0.0) << name;
        }
    }
}

TEST(MaterialLibrary, CompressionClosureIsReadAndBounded) {
    nlohmann::json doc = readJson(hvi::test::dataPath("material/user_library.json"));
    nlohmann::json& al = doc["materials"]["MyAl"];
    al["strength"] = {{"type", "johnson_cook"},
                      {"A_MPa", 289.6},
                      {"B_MPa", 203.4},
                      {"n", 0.35},
                      {"C", 0.011},
                      {"m", 1.34},
                      {"source", "test"}};
    al["elastic"] = {{"shear_modulus_GPa", 27.6}, {"source", "test"}};
    al["thermal"] = {{"specific_heat_J_kgK", 885.0},
                     {"room_temperature_K", 294.0},
                     {"melt_temperature_K", 925.0},
                     {"source", "test"}};
    doc["materials"]["MyAl"]["failure"] = {{"type", "johnson_cook"},
                                           {"D1", -0.77},
                                           {"D2", 1.45},
                                           {"D3", -0.47},
                                           {"D4", 0.0},
                                           {"D5", 1.6},
                                           {"compression_closure", 0.5},
                                           {"cyclic_degradation", 0.25},
                                           {"source", "test"}};
    const auto library = MaterialLibrary::fromJson(doc, "doc");
    EXPECT_EQ(std::get<JohnsonCookDamage>(library.get("MyAl").failure).compressionClosure, 0.5);
    EXPECT_EQ(std::get<JohnsonCookDamage>(library.get("MyAl").failure).cyclicDegradation, 0.25);
    doc["materials"]["MyAl"]["failure"]["cyclic_degradation"] = -0.1;
    const std::string negative = inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "doc"); });
    EXPECT_NE(negative.find("doc: /materials/MyAl/failure/cyclic_degradation"), std::string::npos)
        << negative;
    doc["materials"]["MyAl"]["failure"]["cyclic_degradation"] = 0.25;
    doc["materials"]["MyAl"]["failure"]["compression_closure"] = 1.5;
    const std::string message = inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "doc"); });
    EXPECT_NE(message.find("doc: /materials/MyAl/failure/compression_closure: must be at most 1, "
                           "got 1.5"),
              std::string::npos)
        << message;
}

TEST(MaterialLibrary, BadSpallStrengthIsReportedByPointer) {
    nlohmann::json doc = readJson(hvi::test::dataPath("material/user_library.json"));
    doc["materials"]["MyAl"]["spall"] = {
        {"strength_GPa", -1.2}, {"rate_exponent", 0.06}, {"source", "test"}};
    std::string message = inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "doc"); });
    EXPECT_NE(message.find("doc: /materials/MyAl/spall/strength_GPa: must be > 0, got -1.2"),
              std::string::npos)
        << message;
    doc["materials"]["MyAl"]["spall"] = {{"strength_GPa", 1.2}, {"source", "test"}};
    doc["materials"]["MyAl"].erase("strength");
    message = inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "doc"); });
    EXPECT_NE(message.find("/materials/MyAl/strength: missing (required with a spall strength)"),
              std::string::npos)
        << message;
}

TEST(MaterialLibrary, CumulativeSpallIsReadAndCheckedByPointer) {
    nlohmann::json doc = readJson(hvi::test::dataPath("material/user_library.json"));
    doc["materials"]["MyAl"] =
        nlohmann::json::parse(MaterialLibrary::builtin().get("Al6061-T6").definitionJson);
    doc["materials"]["MyAl"]["spall"] = {{"strength_GPa", 3.0},
                                         {"source", "test"},
                                         {"tuler_butcher",
                                          {{"threshold_GPa", 1.0},
                                           {"exponent", 2.0},
                                           {"critical_integral_GPa_us", 0.2},
                                           {"source", "test"}}}};
    const MaterialLibrary lib = MaterialLibrary::fromJson(doc, "doc");
    const auto& c = lib.get("MyAl").spall->cumulative;
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->thresholdGPa, 1.0);
    EXPECT_EQ(c->exponent, 2.0);
    EXPECT_EQ(c->criticalIntegral, 0.2);
    doc["materials"]["MyAl"]["spall"]["tuler_butcher"]["threshold_GPa"] = 3.5;
    std::string message = inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "doc"); });
    EXPECT_NE(message.find("doc: /materials/MyAl/spall/tuler_butcher/threshold_GPa: is not below "
                           "strength_GPa"),
              std::string::npos)
        << message;
    doc["materials"]["MyAl"]["spall"]["tuler_butcher"]["threshold_GPa"] = 1.0;
    doc["materials"]["MyAl"]["spall"]["tuler_butcher"]["K"] = 0.2;
    message = inputErrorMessage([&] { MaterialLibrary::fromJson(doc, "doc"); });
    EXPECT_NE(message.find("/materials/MyAl/spall/tuler_butcher/K: unknown key"), std::string::npos)
        << message;
}
