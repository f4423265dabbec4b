// The run-file field table: unit strings agree with the declared dimensions, CGS factors are
// right, names follow the conventions, and every struct member is bound exactly once.
#include "Tolerance.hpp"
#include "io/OutputFields.hpp"

#include <cctype>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <string>

using namespace hvi::io;

namespace {

/// The unit strings the table may use, with their dimensions in (mm, mg, us) -- written
/// independently of the table, from docs/conventions.md.
const std::map<std::string, UnitDimensions>& knownUnits() {
    static const std::map<std::string, UnitDimensions> units = {
        {"-", {0, 0, 0}},     {"mm", {1, 0, 0}},        {"mg", {0, 1, 0}},    {"us", {0, 0, 1}},
        {"km/s", {1, 0, -1}}, {"g/cm3", {-3, 1, 0}},    {"GPa", {-1, 1, -2}}, {"MJ/kg", {2, 0, -2}},
        {"J", {2, 1, -2}},    {"mg*mm/us", {1, 1, -1}},
    };
    return units;
}

std::vector<std::span<const FieldSpec>> allTables() {
    return {particleFieldSpecs(), nodeFieldSpecs(), elementFieldSpecs(), historyColumnSpecs()};
}

} // namespace

TEST(OutputFields, UnitStringsMatchDimensions) {
    for (auto table : allTables()) {
        for (const auto& spec : table) {
            auto it = knownUnits().find(std::string(spec.units));
            ASSERT_NE(it, knownUnits().end()) << spec.name << ": unknown unit " << spec.units;
            EXPECT_EQ(it->second, spec.dimensions) << spec.name << " [" << spec.units << "]";
        }
    }
}

TEST(OutputFields, CgsFactorsOfTheHydrocodeUnits) {
    // Exact powers of ten apart from rounding in pow(): 1e-15 relative is a few ulps.
    const double rtol = 1e-15;
    EXPECT_TRUE(hvi::test::near("mm in cm", cgsConversionFactor(kLength), 0.1, 0, rtol));
    EXPECT_TRUE(hvi::test::near("km/s in cm/s", cgsConversionFactor(kVelocity), 1e5, 0, rtol));
    EXPECT_TRUE(hvi::test::near("g/cm3 in g/cm3", cgsConversionFactor(kDensity), 1.0, 0, rtol));
    EXPECT_TRUE(hvi::test::near("GPa in Ba", cgsConversionFactor(kPressure), 1e10, 0, rtol));
    EXPECT_TRUE(hvi::test::near("J in erg", cgsConversionFactor(kEnergy), 1e7, 0, rtol));
    EXPECT_TRUE(
        hvi::test::near("MJ/kg in erg/g", cgsConversionFactor(kSpecificEnergy), 1e10, 0, rtol));
    EXPECT_TRUE(
        hvi::test::near("mg*mm/us in g*cm/s", cgsConversionFactor(kMomentum), 1e2, 0, rtol));
}

TEST(OutputFields, NamesAreCamelCaseAndDescribed) {
    for (auto table : allTables()) {
        std::set<std::string_view> names;
        for (const auto& spec : table) {
            ASSERT_FALSE(spec.name.empty());
            EXPECT_TRUE(std::isupper(static_cast<unsigned char>(spec.name[0]))) << spec.name;
            for (char c : spec.name) {
                EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c))) << spec.name;
            }
            EXPECT_GT(spec.description.size(), 10u) << spec.name;
            EXPECT_TRUE(names.insert(spec.name).second) << "duplicate " << spec.name;
        }
    }
}

TEST(OutputFields, TheFieldsTheSolverIsPromised) {
    const std::vector<std::string> particle = {"Z",
                                               "R",
                                               "Vz",
                                               "Vr",
                                               "Mass",
                                               "Density",
                                               "Pressure",
                                               "InternalEnergy",
                                               "SmoothingLength",
                                               "Damage",
                                               "PlasticStrain",
                                               "StressDeviator",
                                               "BodyId",
                                               "Alive"};
    ASSERT_EQ(particleFieldSpecs().size(), particle.size());
    for (std::size_t i = 0; i < particle.size(); ++i) {
        EXPECT_EQ(particleFieldSpecs()[i].name, particle[i]);
    }
    EXPECT_EQ(findFieldSpec(particleFieldSpecs(), "StressDeviator")->components, 3);
    EXPECT_EQ(findFieldSpec(particleFieldSpecs(), "Alive")->type, ElementType::UInt8);
    EXPECT_EQ(findFieldSpec(particleFieldSpecs(), "BodyId")->type, ElementType::Int32);
    EXPECT_EQ(findFieldSpec(elementFieldSpecs(), "Connectivity")->components, 4);
    EXPECT_EQ(findFieldSpec(elementFieldSpecs(), "Connectivity")->type, ElementType::Int32);
    EXPECT_EQ(findFieldSpec(historyColumnSpecs(), "MomentumZ")->units, "mg*mm/us");
    EXPECT_EQ(findFieldSpec(historyColumnSpecs(), "Step")->type, ElementType::Int64);
    EXPECT_EQ(findFieldSpec(nodeFieldSpecs(), "Vr")->units, "km/s");
    EXPECT_EQ(findFieldSpec(particleFieldSpecs(), "NoSuchField"), nullptr);
}

TEST(OutputFields, EveryMemberIsBoundOnce) {
    // Give each field a distinct size through the table, then read the sizes back through
    // the table: a member bound twice would show the same size twice.
    ParticleFields fields;
    std::size_t next = 1;
    forEachField(fields, [&](const FieldSpec&, auto& values) { values.resize(next++); });
    std::set<std::size_t> seen;
    forEachField(fields, [&](const FieldSpec& spec, auto& values) {
        EXPECT_TRUE(seen.insert(values.size()).second) << spec.name;
    });
    EXPECT_EQ(seen.size(), particleFieldSpecs().size());
    // And the names bind the members they say.
    EXPECT_EQ(fields.z.size(), 1u);
    EXPECT_EQ(fields.vr.size(), 4u);
    EXPECT_EQ(fields.alive.size(), particleFieldSpecs().size());
}

TEST(OutputFields, ViewOfOwnedFieldsSharesTheStorage) {
    ParticleFields fields;
    fields.z = {1.0, 2.0};
    fields.alive = {1, 0};
    fields.stressDeviator = {1, 2, 3, 4, 5, 6};
    const ParticleFieldsView view = viewOf(fields);
    EXPECT_EQ(view.z.data(), fields.z.data());
    EXPECT_EQ(view.z.size(), 2u);
    EXPECT_EQ(view.alive.data(), fields.alive.data());
    EXPECT_EQ(view.stressDeviator.size(), 6u);
    EXPECT_TRUE(view.damage.empty());
}

TEST(OutputFields, RelativeEnergyErrorCountsDeletedEnergy) {
    // 100 J at start; 90 J left in the calculation, 10 J carried away: no error.
    EXPECT_EQ(relativeEnergyError(90.0, 10.0, 100.0), 0.0);
    EXPECT_EQ(relativeEnergyError(91.0, 10.0, 100.0), 0.01);
    EXPECT_EQ(relativeEnergyError(5.0, 0.0, 0.0), 0.0);
}
