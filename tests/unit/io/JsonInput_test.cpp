// JSON input checks: every class of bad input gives an issue with the right JSON pointer.
#include "TestPaths.hpp"
#include "io/JsonInput.hpp"

#include <filesystem>
#include <gtest/gtest.h>

using hvi::InputError;
using hvi::io::parseJsonText;
using hvi::io::validateAgainstSchema;
using nlohmann::json;

namespace {

json goodConstraints() {
    return json::parse(R"({"threat": {"diameter_mm": 3.6, "velocity_km_s": 6.76},
                           "shield": {"type": "whipple", "bumper_mm": 2.0,
                                      "rear_wall_mm": 2.0, "standoff_mm": 50.8}})");
}

/// Runs validation and returns the issues (empty when valid).
std::vector<hvi::InputIssue> issuesOf(const json& doc) {
    try {
        validateAgainstSchema(doc, "constraints", "c.json");
    } catch (const InputError& e) {
        return e.issues();
    }
    return {};
}

} // namespace

TEST(JsonInput, GoodDocumentPasses) {
    EXPECT_TRUE(issuesOf(goodConstraints()).empty());
}

TEST(JsonInput, NegativeValueNamesPointerAndUnit) {
    json doc = goodConstraints();
    doc["threat"]["diameter_mm"] = -1.0;
    auto issues = issuesOf(doc);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].pointer, "/threat/diameter_mm");
    EXPECT_NE(issues[0].problem.find("-1"), std::string::npos) << issues[0].format();
    EXPECT_NE(issues[0].expected.find("[mm]"), std::string::npos) << issues[0].format();
}

TEST(JsonInput, UnknownKeyIsRejectedByName) {
    json doc = goodConstraints();
    doc["shield"]["bumper_thicknes_mm"] = 1.0;
    auto issues = issuesOf(doc);
    ASSERT_EQ(issues.size(), 1u) << issues[0].format();
    EXPECT_EQ(issues[0].pointer, "/shield/bumper_thicknes_mm");
    EXPECT_NE(issues[0].problem.find("unknown key"), std::string::npos);
}

TEST(JsonInput, MissingKeyIsNamed) {
    json doc = goodConstraints();
    doc["threat"].erase("velocity_km_s");
    auto issues = issuesOf(doc);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].pointer, "/threat/velocity_km_s");
    EXPECT_NE(issues[0].problem.find("missing"), std::string::npos);
    EXPECT_NE(issues[0].expected.find("[km/s]"), std::string::npos) << issues[0].format();
}

TEST(JsonInput, WrongTypeIsReported) {
    json doc = goodConstraints();
    doc["threat"]["velocity_km_s"] = "fast";
    auto issues = issuesOf(doc);
    ASSERT_FALSE(issues.empty());
    EXPECT_EQ(issues[0].pointer, "/threat/velocity_km_s");
}

TEST(JsonInput, ZeroVelocityIsOutOfRange) {
    json doc = goodConstraints();
    doc["threat"]["velocity_km_s"] = 0.0;
    auto issues = issuesOf(doc);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].pointer, "/threat/velocity_km_s");
    EXPECT_NE(issues[0].expected.find("> 0"), std::string::npos) << issues[0].format();
}

TEST(JsonInput, AllIssuesReportedTogether) {
    json doc = goodConstraints();
    doc["threat"]["diameter_mm"] = -1.0;
    doc["shield"]["standoff_mm"] = -5.0;
    EXPECT_EQ(issuesOf(doc).size(), 2u);
}

TEST(JsonInput, NaNTokenNamesItsKey) {
    try {
        parseJsonText(R"({"threat": {"diameter_mm": NaN, "velocity_km_s": 6}})", "c.json");
        FAIL() << "NaN accepted";
    } catch (const InputError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_EQ(e.issues()[0].pointer, "/threat/diameter_mm");
    }
}

TEST(JsonInput, SyntaxErrorGivesLineAndColumn) {
    try {
        parseJsonText("{\n \"a\": 1,\n}", "c.json");
        FAIL() << "bad JSON accepted";
    } catch (const InputError& e) {
        EXPECT_NE(e.issues()[0].problem.find("line 3"), std::string::npos) << e.what();
        EXPECT_EQ(e.issues()[0].problem.find("json.exception"), std::string::npos) << e.what();
    }
}

TEST(JsonInput, DefaultsAreFilledIn) {
    json resolved = hvi::io::withSchemaDefaults(goodConstraints(), "constraints");
    EXPECT_EQ(resolved["threat"]["angle_deg"], 0);
    EXPECT_EQ(resolved["threat"]["material"], "Al6061-T6");
    EXPECT_EQ(resolved["shield"]["rear_wall_material"], "Al6061-T6");
    EXPECT_EQ(resolved["options"]["thesis_compat"], false);
    EXPECT_EQ(resolved["mode"], "performance");
}

// Hostile texts (issue #25). None may crash the reader, and each gets one issue that says
// where the problem is.
namespace {

std::string nestedArrays(std::size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

/// The issues parseJsonText raises for `text` (empty when it parses).
std::vector<hvi::InputIssue> parseIssues(const std::string& text) {
    try {
        parseJsonText(text, "c.json");
    } catch (const InputError& e) {
        return e.issues();
    }
    return {};
}

} // namespace

TEST(JsonInput, DeepNestingIsRefusedWithItsPointer) {
    const auto issues = parseIssues("{\"summary\": {\"notes\": " + nestedArrays(30000) + "}}");
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].pointer.rfind("/summary/notes/0/0", 0), 0u) << issues[0].format();
    EXPECT_NE(issues[0].problem.find("256 levels"), std::string::npos) << issues[0].format();
}

TEST(JsonInput, NestingUpToTheLimitIsAccepted) {
    // The document's own object and 255 arrays inside it: 256 levels.
    EXPECT_NO_THROW(parseJsonText("{\"a\": " + nestedArrays(255) + "}", "c.json"));
    EXPECT_FALSE(parseIssues("{\"a\": " + nestedArrays(256) + "}").empty());
}

TEST(JsonInput, LongWhitespaceRunInABrokenFileIsASyntaxError) {
    const auto issues = parseIssues("{\"threat\":" + std::string(100000, '\n'));
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_NE(issues[0].problem.find("not valid JSON"), std::string::npos) << issues[0].format();
    EXPECT_NE(issues[0].problem.find("line 100001"), std::string::npos) << issues[0].format();
}

TEST(JsonInput, NonFiniteTokensAreFoundOutsideStringsOnly) {
    const auto issues =
        parseIssues(R"({"a\"b": "x\": NaN, ", "c/d": [1, -Infinity, {"e": inf}], "f": "NaN"})");
    ASSERT_EQ(issues.size(), 2u);
    EXPECT_EQ(issues[0].pointer, "/c~1d/1");
    EXPECT_NE(issues[0].problem.find("is -Infinity, not a finite number"), std::string::npos)
        << issues[0].format();
    EXPECT_EQ(issues[1].pointer, "/c~1d/2/e");
}

TEST(JsonInput, NonFiniteTokenInABrokenFileIsASyntaxError) {
    const auto issues = parseIssues(R"({"a": NaN, "b": })");
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_NE(issues[0].problem.find("not valid JSON"), std::string::npos) << issues[0].format();
}

TEST(JsonInput, NumberBeyondADoubleNamesItsPointer) {
    const auto issues = parseIssues(R"({"threat": {"diameter_mm": 1e400}})");
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].pointer, "/threat/diameter_mm");
    EXPECT_NE(issues[0].problem.find("1e400"), std::string::npos) << issues[0].format();
}

TEST(JsonInput, DirectoryIsNamedAsSuch) {
    const auto directory = hvi::test::tempPath("a-directory.json");
    std::filesystem::create_directories(directory);
    try {
        hvi::io::readJsonFile(directory.string());
        FAIL() << "a directory was read as JSON";
    } catch (const InputError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_NE(e.issues()[0].problem.find("is a directory"), std::string::npos) << e.what();
    }
}
