// The tool inputs of one validation case: what a designer would write for the same shot.
//   - the scene writer's input (foam2layers for Whipple shields, `panel.type` whipple, and foam
//     panels; hcomb2rings for honeycomb panels), without numerics: the workflow gives the
//     spacing as a flag;
//   - ble-size's constraints for the NASA JSC equation of the same shield (for foam panels
//     with the panel's measured areal density where the data has it, as the foam BLE was
//     fitted; the hydrocode's foam takes the nominal relative density, the source study's
//     mass input).
#pragma once

#include "validation/ValidationCase.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace hvi::validation {

/// "foam2layers" or "hcomb2rings".
std::string sceneWriterOf(const Case& c);

/// The scene writer's input document.
nlohmann::json panelInput(const Case& c);

/// ble-size's constraints document (performance mode).
nlohmann::json bleConstraints(const Case& c);

} // namespace hvi::validation
