#include "scene/SceneLibrary.hpp"

#include <nlohmann/json.hpp>

namespace hvi::scene {

material::MaterialLibrary sceneLibrary(const nlohmann::json& sceneMaterials,
                                       const std::string& file) {
    material::MaterialLibrary library = material::MaterialLibrary::builtin();
    if (sceneMaterials.is_object() && !sceneMaterials.empty()) {
        library.merge(material::MaterialLibrary::fromJson(
            nlohmann::json{{"description", "scene materials"}, {"materials", sceneMaterials}},
            file + " /materials"));
    }
    return library;
}

} // namespace hvi::scene
