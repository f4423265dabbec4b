// Reading JSON inputs: parse, validate against a JSON Schema (draft 7, valijson), and turn
// every problem into an InputIssue that names the file and the JSON pointer.
//
// The schemas are compiled in (schemas/*.json, see io/Resources.hpp) and carry a
// "description" with the unit on every property; that description becomes the
// "(what was expected)" part of an error line.
#pragma once

#include "core/Error.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace hvi::io {

/// Parses a JSON file ("-" reads standard input). Throws InputError naming the file and the
/// line/column of a syntax error, or that the file is a directory or cannot be read.
nlohmann::json readJsonFile(const std::string& path);

/// Parses JSON text; `label` names the source in error messages. Refuses, with the JSON
/// pointer, nesting deeper than kMaxJsonDepth and NaN, Infinity or numbers beyond a double
/// (see io/JsonTextScan.hpp), so every document it returns is safe to walk recursively.
nlohmann::json parseJsonText(const std::string& text, const std::string& label);

/// Validates `document` against the embedded schema `schemaName` (e.g. "constraints").
/// Throws InputError listing every violation (unknown keys, wrong types, out-of-range
/// values, missing keys), each located by JSON pointer.
void validateAgainstSchema(const nlohmann::json& document, const std::string& schemaName,
                           const std::string& file);

/// The embedded schema text as parsed JSON (for --print-schema and for defaults).
const nlohmann::json& schema(const std::string& schemaName);

/// Fills in the schema's "default" values for absent properties, recursively through
/// "properties" (and the "then" branch of if/then that matches), so an output can echo
/// the input it actually ran with.
nlohmann::json withSchemaDefaults(const nlohmann::json& document, const std::string& schemaName);

/// Rejects NaN and infinities anywhere in a document (JSON itself cannot carry them, but
/// documents assembled from flags can). Throws InputError with the pointer.
void requireFiniteNumbers(const nlohmann::json& document, const std::string& file);

} // namespace hvi::io
