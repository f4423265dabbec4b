// Schemas (schemas/*.json) and data tables (data/*.json) compiled into the library, so a
// tool never depends on finding files next to itself. Keys are "schemas/NAME.json" and
// "data/NAME.json".
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hvi::resources {

const std::map<std::string, std::string_view>& all();

/// The text of one embedded resource; throws std::out_of_range naming it if absent.
inline std::string_view get(const std::string& key) {
    const auto& table = all();
    auto it = table.find(key);
    if (it == table.end()) {
        throw std::out_of_range("no embedded resource '" + key + "'");
    }
    return it->second;
}

} // namespace hvi::resources
