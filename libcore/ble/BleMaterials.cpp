#include "ble/BleMaterials.hpp"

#include "io/Resources.hpp"

#include <map>
#include <nlohmann/json.hpp>

namespace hvi::ble {

namespace {
const std::map<std::string, BleMaterial>& table() {
    static const std::map<std::string, BleMaterial> materials = [] {
        std::map<std::string, BleMaterial> out;
        const auto doc = nlohmann::json::parse(resources::get("data/ble_materials.json"));
        for (const auto& [name, entry] : doc.at("materials").items()) {
            BleMaterial m;
            m.name = name;
            m.densityGCm3 = entry.at("density_g_cm3");
            if (entry.contains("yield_ksi")) {
                m.yieldKsi = entry.at("yield_ksi").get<double>();
            }
            if (entry.contains("sound_speed_km_s")) {
                m.soundSpeedKmS = entry.at("sound_speed_km_s").get<double>();
            }
            if (entry.contains("brinell_hardness")) {
                m.brinellHardness = entry.at("brinell_hardness").get<double>();
            }
            m.source = entry.value("source", "");
            out.emplace(name, m);
        }
        return out;
    }();
    return materials;
}
} // namespace

const BleMaterial* findBleMaterial(const std::string& name) {
    auto it = table().find(name);
    return it == table().end() ? nullptr : &it->second;
}

std::vector<std::string> bleMaterialNames() {
    std::vector<std::string> names;
    for (const auto& [name, m] : table()) {
        names.push_back(name);
    }
    return names;
}

} // namespace hvi::ble
