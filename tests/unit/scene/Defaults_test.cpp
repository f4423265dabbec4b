// The calibrated numerical defaults (scene/Defaults.hpp) are the ones the schemas fill in: a
// schema default that drifts from the header fails here, naming the schema and its pointer.
// The whole tree of every compiled-in schema is searched, so a schema that starts to carry one
// of these keys is held to it too.
#include "io/Resources.hpp"
#include "scene/Defaults.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>

using namespace hvi;
using nlohmann::json;

namespace {

/// Counts and checks every "default" of a property named `key` in `node`.
int checkDefaults(const json& node, const std::string& pointer, const std::string& schema,
                  const std::string& key, double expected) {
    int found = 0;
    if (node.is_object()) {
        for (const auto& [name, child] : node.items()) {
            if (name == key && child.is_object() && child.contains("default")) {
                EXPECT_DOUBLE_EQ(child["default"].get<double>(), expected)
                    << schema << " " << pointer << "/" << name << "/default";
                ++found;
            }
            found += checkDefaults(child, pointer + "/" + name, schema, key, expected);
        }
    } else if (node.is_array()) {
        for (std::size_t i = 0; i < node.size(); ++i) {
            found +=
                checkDefaults(node[i], pointer + "/" + std::to_string(i), schema, key, expected);
        }
    }
    return found;
}

} // namespace

TEST(Defaults, SchemasFillTheHeadersValues) {
    int spacing = 0, erosion = 0;
    for (const auto& [name, text] : resources::all()) {
        if (name.rfind("schemas/", 0) != 0) {
            continue;
        }
        const json schema = json::parse(text);
        spacing += checkDefaults(schema, "", name, "particle_spacing_mm",
                                 scene::kDefaultParticleSpacingMm);
        erosion += checkDefaults(schema, "", name, "erosion_factor", scene::kDefaultErosionFactor);
    }
    // The scene and both panel schemas fill each.
    EXPECT_EQ(spacing, 3);
    EXPECT_EQ(erosion, 3);
}

TEST(Defaults, HelpTextPrintsTheShortForm) {
    EXPECT_EQ(scene::defaultText(0.015), "0.015");
    EXPECT_EQ(scene::defaultText(1.5), "1.5");
    EXPECT_EQ(scene::defaultText(2.0), "2");
}
