// One linear pass over JSON text before it is parsed, in place (no copy of the text) and
// without recursion, so that a hostile file cannot exhaust the stack or the memory here:
//
// - nesting: every later walk of a document (copies, dumps, schema validation, the finite-
//   number check) recurses once per level, and a value nested 30,000 levels deep overflowed
//   the stack. Documents nested deeper than kMaxJsonDepth are refused before any such walk.
// - values JSON cannot hold but hand-edited files and other tools write (NaN, Infinity,
//   numbers beyond the range of a double), each located by the JSON pointer of its key;
//   the parser would only give a line and column, or for 1e400 not even that.
#pragma once

#include "core/Error.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hvi::io {

/// Objects and arrays nested deeper than this are refused. Our inputs nest at most about
/// six levels; 256 leaves room for any hand-made structure and keeps every recursive walk
/// a few tens of kilobytes of stack.
inline constexpr std::size_t kMaxJsonDepth = 256;

struct JsonTextScan {
    /// Set when the nesting passes the limit; the scan stops there.
    std::optional<InputIssue> tooDeep;
    /// NaN and Infinity tokens and numbers beyond the range of a double, in text order.
    std::vector<InputIssue> nonFinite;
    /// Whether the text is one JSON document once NaN and Infinity are read as numbers.
    /// When it is not, the parser's syntax error (line and column) is the better message.
    bool wellFormed = false;
};

/// Scans `text`; `label` names the file in the issues. Time linear in the text's length,
/// memory proportional to the nesting depth (at most `maxDepth`).
JsonTextScan scanJsonText(std::string_view text, const std::string& label,
                          std::size_t maxDepth = kMaxJsonDepth);

} // namespace hvi::io
