// The scene hvi-run runs, read and checked before anything is allocated: the file (or stdin),
// the command line's overrides written into the document (so the run file records what ran),
// non-finite numbers, the schema, the material library (the built-in one, the scene's own
// blocks, a --materials file), the parsed scene with its layout rules (scene::parseScene),
// the point budget against the memory given, and the warnings for what is legal but
// suspicious. `hvi-run --check` stops here; the fuzz target of hvi-run's input calls it too.
#pragma once

#include "material/MaterialLibrary.hpp"
#include "scene/Scene.hpp"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hvi::app {

/// Command-line values laid over the scene; zero or empty leaves the scene's own.
struct SceneOverrides {
    double resolutionMm = 0.0;    ///< every body's spacing and the FE element size
    double endTimeUs = 0.0;       ///< /run/end_time_us
    double snapshotEveryUs = 0.0; ///< /output/snapshot_every_us
    std::string materialsFile;    ///< a material library laid over the built-in one
};

struct RunScene {
    material::MaterialLibrary library;
    scene::Scene scene;
    double estimatedPoints = 0.0;      ///< SPH particles, FE elements and their slots
    double memoryLimitBytes = 0.0;     ///< what the point budget was checked against
    std::vector<std::string> warnings; ///< legal but most likely a mistake
};

/// Reads and checks `file` ("-" for stdin). Throws InputError naming the file and the JSON
/// pointer of the first problem (or of every schema issue at once).
RunScene loadRunScene(const std::string& file, const SceneOverrides& overrides,
                      double memoryLimitBytes);

} // namespace hvi::app
