// The material table the ballistic limit equations read (data/ble_materials.json, compiled
// in): density, yield stress, sound speed and Brinell hardness in the JSC equations' units.
// Source: NASA/TM-2009-214789 Table 1 unless an entry says otherwise.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hvi::ble {

struct BleMaterial {
    std::string name;
    double densityGCm3 = 0.0;
    std::optional<double> yieldKsi;         ///< absent for projectile-only entries
    std::optional<double> soundSpeedKmS;    ///< bulk sound speed C [km/s]
    std::optional<double> brinellHardness;  ///< BHN
    std::string source;
};

/// The entry for `name`, or nullptr.
const BleMaterial* findBleMaterial(const std::string& name);

/// All names, sorted (for error messages and --list-materials).
std::vector<std::string> bleMaterialNames();

} // namespace hvi::ble
