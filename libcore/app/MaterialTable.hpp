// The toolkit's material names and densities (data/ble_materials.json, compiled in). The
// scene writers need the density of the core material for the areal masses, and check that
// every material they write into a scene is one the toolkit knows.
#pragma once

#include <optional>
#include <string>

namespace hvi::app {

/// Density [g/cm^3] of a material of the table, or nothing when the name is not in it.
std::optional<double> materialDensityGCm3(const std::string& name);

/// The table's material names, comma-separated (for "expected" texts).
std::string materialNameList();

} // namespace hvi::app
