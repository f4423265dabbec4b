#include "app/MaterialTable.hpp"

#include "io/Resources.hpp"

#include <nlohmann/json.hpp>

namespace hvi::app {

namespace {
const nlohmann::json& materials() {
    static const nlohmann::json table =
        nlohmann::json::parse(resources::get("data/ble_materials.json")).at("materials");
    return table;
}
} // namespace

std::optional<double> materialDensityGCm3(const std::string& name) {
    const auto& table = materials();
    auto it = table.find(name);
    if (it == table.end() || !it->contains("density_g_cm3")) {
        return std::nullopt;
    }
    return it->at("density_g_cm3").get<double>();
}

std::string materialNameList() {
    std::string names;
    for (const auto& [name, entry] : materials().items()) {
        names += (names.empty() ? "" : ", ") + name;
    }
    return names;
}

} // namespace hvi::app
