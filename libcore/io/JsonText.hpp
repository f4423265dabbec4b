// A JSON value as text, for every file and message the toolkit writes. Strings that are not
// valid UTF-8 (a damaged run file's attribute, a file name given in another encoding) come
// out with U+FFFD in place of the bad bytes, where nlohmann::json's plain dump() would throw
// and turn a readable result into an internal error.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace hvi::io {

/// `value` as JSON text; `indent` as for nlohmann::json::dump (-1: one line).
inline std::string jsonText(const nlohmann::json& value, int indent = -1) {
    return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace hvi::io
