// The material library a scene runs with: the built-in library with the scene's own
// /materials laid over it (same schema as data/hydro_materials.json).
#pragma once

#include "material/MaterialLibrary.hpp"
#include "scene/Scene.hpp"

namespace hvi::scene {

material::MaterialLibrary sceneLibrary(const nlohmann::json& sceneMaterials,
                                       const std::string& file);

} // namespace hvi::scene
