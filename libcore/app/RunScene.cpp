#include "app/RunScene.hpp"

#include "core/Error.hpp"
#include "io/JsonInput.hpp"
#include "scene/BodyLayout.hpp"
#include "scene/PointBudget.hpp"
#include "scene/SceneLibrary.hpp"

#include <numeric>

namespace hvi::app {

using nlohmann::json;

namespace {
void applyOverrides(json& doc, const SceneOverrides& o) {
    if (o.resolutionMm > 0.0) {
        doc["sph"]["particle_spacing_mm"] = o.resolutionMm;
        if (doc.contains("fe") && doc["fe"].is_object() && doc["fe"].contains("element_size_mm")) {
            doc["fe"]["element_size_mm"] = o.resolutionMm; // else it follows the particle spacing
        }
        if (doc.contains("bodies") && doc["bodies"].is_array()) {
            for (auto& body : doc["bodies"]) {
                if (body.is_object() && body.contains("spacing_mm")) {
                    body["spacing_mm"] = o.resolutionMm;
                }
            }
        }
    }
    if (o.endTimeUs > 0.0) {
        doc["run"]["end_time_us"] = o.endTimeUs;
    }
    if (o.snapshotEveryUs > 0.0) {
        doc["output"]["snapshot_every_us"] = o.snapshotEveryUs;
    }
}
} // namespace

RunScene loadRunScene(const std::string& file, const SceneOverrides& overrides,
                      double memoryLimitBytes) {
    json doc = io::readJsonFile(file);
    if (!doc.is_object()) {
        throw InputError(file, "", "is not a JSON object", "a scene (hvi-run --print-schema)");
    }
    applyOverrides(doc, overrides);
    io::requireFiniteNumbers(doc, file);
    io::validateAgainstSchema(doc, "scene", file);
    auto library = scene::sceneLibrary(doc.value("materials", json::object()), file);
    if (!overrides.materialsFile.empty()) {
        library.merge(material::MaterialLibrary::fromFile(overrides.materialsFile, &library));
    }
    scene::Scene parsed = scene::parseScene(doc, file, library.names());
    scene::requirePointBudget(parsed, file, memoryLimitBytes);
    const auto points = scene::estimatedPoints(parsed);
    auto warnings = scene::bodyLayoutWarnings(parsed);
    return {std::move(library), std::move(parsed),
            std::accumulate(points.begin(), points.end(), 0.0), memoryLimitBytes,
            std::move(warnings)};
}

} // namespace hvi::app
