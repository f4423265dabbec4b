#include "io/JsonInput.hpp"

#include "io/JsonText.hpp"
#include "io/JsonTextScan.hpp"
#include "io/Resources.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validator.hpp>

namespace hvi::io {

using nlohmann::json;

namespace {

/// nlohmann's message without its "[json.exception.parse_error.101] " tag.
std::string withoutTag(const std::string& message) {
    const auto pos = message.find("] ");
    return pos == std::string::npos ? message : message.substr(pos + 2);
}

/// The whole content of an open file, read in one allocation when its size is known (a
/// regular file), so a large input is held once, not twice.
std::string readAll(std::istream& in) {
    std::string text;
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size > 0) {
        text.resize(static_cast<std::size_t>(size));
        in.seekg(0, std::ios::beg);
        in.read(text.data(), size);
        text.resize(static_cast<std::size_t>(in.gcount()));
        return text;
    }
    in.clear();
    in.seekg(0, std::ios::beg);
    in.clear();
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return text;
}

} // namespace

json parseJsonText(const std::string& text, const std::string& label) {
    // Before the parser: a document too deep for the recursive walks that follow, and the
    // values JSON cannot hold (NaN, Infinity, 1e400), which the scan can place by pointer.
    JsonTextScan scan = scanJsonText(text, label);
    if (scan.tooDeep) {
        throw InputError({*scan.tooDeep});
    }
    if (scan.wellFormed && !scan.nonFinite.empty()) {
        throw InputError(std::move(scan.nonFinite));
    }
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        // A syntax error ("parse error at line 3, column 5: ..."), or a number the scan
        // missed; either way the text is not a document we can read.
        throw InputError(label, "", "not valid JSON: " + withoutTag(e.what()), "a JSON document");
    }
}

json readJsonFile(const std::string& path) {
    if (path == "-") {
        return parseJsonText(readAll(std::cin), path);
    }
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        throw InputError(path, "", "is a directory", "a JSON file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(path, "", "cannot be read", "an existing, readable JSON file");
    }
    const std::string text = readAll(in);
    if (in.bad()) {
        throw InputError(path, "", "cannot be read", "an existing, readable JSON file");
    }
    return parseJsonText(text, path);
}

const json& schema(const std::string& schemaName) {
    static std::mutex guard;
    static std::map<std::string, json> cache;
    std::lock_guard<std::mutex> lock(guard);
    auto it = cache.find(schemaName);
    if (it == cache.end()) {
        const std::string key = "schemas/" + schemaName + ".schema.json";
        it = cache.emplace(schemaName, json::parse(resources::get(key))).first;
    }
    return it->second;
}

namespace {

/// Resolves a local "$ref" ("#/definitions/x") against the schema root.
const json* resolveRef(const json& root, const json* node) {
    for (int depth = 0; node && node->is_object() && node->contains("$ref") && depth < 16;
         ++depth) {
        const std::string ref = (*node)["$ref"].get<std::string>();
        if (ref.rfind("#", 0) != 0) {
            return node;
        }
        node = &root.at(json::json_pointer(ref.substr(1)));
    }
    return node;
}

/// True when `document` satisfies a discriminating "if" of the simple form used in our
/// schemas: {"properties": {"key": {"const": value}}, "required": ["key"]}.
bool simpleIfMatches(const json& ifSchema, const json& document) {
    if (!document.is_object() || !ifSchema.contains("properties")) {
        return false;
    }
    for (const auto& [key, sub] : ifSchema["properties"].items()) {
        if (!sub.contains("const")) {
            return false;
        }
        auto it = document.find(key);
        if (it == document.end() || *it != sub["const"]) {
            return false;
        }
    }
    return true;
}

/// Collects the property schemas that apply to an object, following $ref, allOf and the
/// matching if/then branches.
void collectProperties(const json& root, const json* node, const json& document,
                       std::map<std::string, const json*>& out) {
    node = resolveRef(root, node);
    if (!node || !node->is_object()) {
        return;
    }
    if (node->contains("properties")) {
        for (const auto& [key, sub] : (*node)["properties"].items()) {
            out[key] = &sub; // unresolved: a "default" may sit beside a "$ref"
        }
    }
    if (node->contains("allOf")) {
        for (const auto& sub : (*node)["allOf"]) {
            collectProperties(root, &sub, document, out);
        }
    }
    if (node->contains("if") && node->contains("then") &&
        simpleIfMatches((*node)["if"], document)) {
        collectProperties(root, &(*node)["then"], document, out);
    }
}

/// The schema node describing the value at `pointer` in `document`, or nullptr.
const json* schemaNodeAt(const json& root, const json& document, const std::string& pointer) {
    const json* node = &root;
    const json* value = &document;
    std::string rest = pointer;
    while (!rest.empty()) {
        auto next = rest.find('/', 1);
        std::string token =
            rest.substr(1, next == std::string::npos ? std::string::npos : next - 1);
        rest = next == std::string::npos ? "" : rest.substr(next);
        node = resolveRef(root, node);
        if (!node) {
            return nullptr;
        }
        if (value && value->is_array() && node->contains("items")) {
            node = &(*node)["items"];
            std::size_t index = 0;
            try {
                index = std::stoul(token);
            } catch (...) {
                return nullptr;
            }
            value = index < value->size() ? &(*value)[index] : nullptr;
            continue;
        }
        std::map<std::string, const json*> properties;
        collectProperties(root, node, value ? *value : json::object(), properties);
        auto it = properties.find(token);
        if (it == properties.end()) {
            return nullptr;
        }
        node = it->second;
        value =
            (value && value->is_object() && value->contains(token)) ? &(*value)[token] : nullptr;
    }
    return node;
}

/// "(what was expected)": the property's description (with its unit) and its bounds.
std::string describe(const json& root, const json* raw) {
    const json* node = resolveRef(root, raw);
    if (!raw || !node || !node->is_object()) {
        return "";
    }
    std::string text = raw->value("description", node->value("description", ""));
    auto addBound = [&](const char* key, const char* op) {
        if (node->contains(key)) {
            text += (text.empty() ? "" : ", ") + std::string(op) + " " + jsonText((*node)[key]);
        }
    };
    addBound("exclusiveMinimum", ">");
    addBound("minimum", ">=");
    addBound("exclusiveMaximum", "<");
    addBound("maximum", "<=");
    if (node->contains("enum")) {
        std::string choices;
        for (const auto& v : (*node)["enum"]) {
            choices += (choices.empty() ? "" : ", ") + jsonText(v);
        }
        text += (text.empty() ? "one of " : "; one of ") + choices;
    }
    return text;
}

std::string escapePointerToken(const std::string& token) {
    std::string out;
    for (char c : token) {
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

/// valijson context ["<root>", "[threat]", "[diameter_mm]"] -> "/threat/diameter_mm".
std::string contextToPointer(const std::vector<std::string>& context) {
    std::string pointer;
    for (const auto& part : context) {
        if (part.size() >= 2 && part.front() == '[' && part.back() == ']') {
            pointer += "/" + escapePointerToken(part.substr(1, part.size() - 2));
        }
    }
    return pointer;
}

/// Rewrites valijson's wording into the short form of our error lines, and spots the
/// unknown-key case so the message names the key.
std::string rewriteProblem(const std::string& description, const json& document,
                           const std::string& pointer, std::string& pointerOut) {
    pointerOut = pointer;
    const std::string unknownMarker = "could not be validated using 'properties' or "
                                      "'additionalProperties' constraints: '";
    if (auto pos = description.find(unknownMarker); pos != std::string::npos) {
        std::string key = description.substr(pos + unknownMarker.size());
        if (auto end = key.rfind('\''); end != std::string::npos) {
            key = key.substr(0, end);
        }
        pointerOut = pointer + "/" + escapePointerToken(key);
        return "unknown key '" + key + "' (misspelt? remove it or use a documented key)";
    }
    const std::string missingMarker = "Missing required property '";
    if (auto pos = description.find(missingMarker); pos != std::string::npos) {
        std::string key = description.substr(pos + missingMarker.size());
        if (auto end = key.rfind('\''); end != std::string::npos) {
            key = key.substr(0, end);
        }
        pointerOut = pointer + "/" + escapePointerToken(key);
        return "required key is missing";
    }
    std::string problem = description;
    try {
        const json& value = document.at(json::json_pointer(pointer));
        problem += " (got " + jsonText(value) + ")";
    } catch (...) {
    }
    return problem;
}

struct CompiledSchema {
    valijson::Schema schema;
};

const valijson::Schema& compiledSchema(const std::string& schemaName) {
    static std::mutex guard;
    static std::map<std::string, std::unique_ptr<CompiledSchema>> cache;
    std::lock_guard<std::mutex> lock(guard);
    auto& slot = cache[schemaName];
    if (!slot) {
        slot = std::make_unique<CompiledSchema>();
        valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
        valijson::adapters::NlohmannJsonAdapter adapter(schema(schemaName));
        parser.populateSchema(adapter, slot->schema);
    }
    return slot->schema;
}

} // namespace

void validateAgainstSchema(const json& document, const std::string& schemaName,
                           const std::string& file) {
    const valijson::Schema& compiled = compiledSchema(schemaName);
    valijson::Validator validator(valijson::Validator::kStrongTypes);
    valijson::ValidationResults results;
    valijson::adapters::NlohmannJsonAdapter target(document);
    if (validator.validate(compiled, target, &results)) {
        return;
    }
    // valijson reports a violation at every level of nesting (the leaf, then each enclosing
    // object and the if/then or allOf that failed). Keep the deepest, most specific ones.
    struct Raw {
        std::string pointer;
        std::string description;
    };
    std::vector<Raw> raw;
    valijson::ValidationResults::Error error;
    while (results.popError(error)) {
        raw.push_back({contextToPointer(error.context), error.description});
    }
    const json& root = schema(schemaName);
    std::vector<InputIssue> issues;
    std::set<std::string> seen;
    for (const auto& candidate : raw) {
        const bool isSummary =
            candidate.description.find("Failed to validate against") != std::string::npos ||
            candidate.description.find("Failed to validate item") != std::string::npos ||
            candidate.description.find("Failed to validate against child schema") !=
                std::string::npos ||
            candidate.description.find("Failed to validate value for property") !=
                std::string::npos ||
            candidate.description.find("Failed to validate against schema associated") !=
                std::string::npos ||
            candidate.description.find("Failed to validate against 'then'") != std::string::npos;
        bool hasDeeper = false;
        for (const auto& other : raw) {
            if (other.pointer.size() > candidate.pointer.size() &&
                other.pointer.rfind(candidate.pointer + "/", 0) == 0) {
                hasDeeper = true;
                break;
            }
        }
        if (isSummary ||
            (hasDeeper &&
             candidate.description.find("could not be validated") == std::string::npos &&
             candidate.description.find("Missing required") == std::string::npos)) {
            continue;
        }
        std::string pointer;
        std::string problem =
            rewriteProblem(candidate.description, document, candidate.pointer, pointer);
        if (!seen.insert(pointer + "|" + problem).second) {
            continue;
        }
        issues.push_back(
            {file, pointer, problem, describe(root, schemaNodeAt(root, document, pointer))});
    }
    if (issues.empty()) {
        issues.push_back({file, "", "does not match the schema '" + schemaName + "'", ""});
    }
    throw InputError(std::move(issues));
}

namespace {
void fillDefaults(const json& root, const json* node, json& value) {
    node = resolveRef(root, node);
    if (!node || !value.is_object()) {
        return;
    }
    std::map<std::string, const json*> properties;
    collectProperties(root, node, value, properties);
    for (const auto& [key, sub] : properties) {
        if (!value.contains(key) && sub && sub->contains("default")) {
            value[key] = (*sub)["default"];
        }
        if (value.contains(key) && value[key].is_object()) {
            fillDefaults(root, sub, value[key]);
        }
        const json* resolvedSub = resolveRef(root, sub);
        if (value.contains(key) && value[key].is_array() && resolvedSub &&
            resolvedSub->contains("items")) {
            for (auto& element : value[key]) {
                fillDefaults(root, &(*resolvedSub)["items"], element);
            }
        }
    }
}

void checkFinite(const json& value, const std::string& pointer, const std::string& file,
                 std::vector<InputIssue>& issues) {
    if (value.is_number_float() && !std::isfinite(value.get<double>())) {
        issues.push_back({file, pointer, "is not a finite number", "a finite value"});
    } else if (value.is_object()) {
        for (const auto& [key, sub] : value.items()) {
            checkFinite(sub, pointer + "/" + escapePointerToken(key), file, issues);
        }
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i) {
            checkFinite(value[i], pointer + "/" + std::to_string(i), file, issues);
        }
    }
}
} // namespace

json withSchemaDefaults(const json& document, const std::string& schemaName) {
    json resolved = document;
    const json& root = schema(schemaName);
    fillDefaults(root, &root, resolved);
    return resolved;
}

void requireFiniteNumbers(const json& document, const std::string& file) {
    std::vector<InputIssue> issues;
    checkFinite(document, "", file, issues);
    if (!issues.empty()) {
        throw InputError(std::move(issues));
    }
}

} // namespace hvi::io
