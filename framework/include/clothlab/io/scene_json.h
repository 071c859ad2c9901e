/// @file scene_json.h
/// @brief Loading and validating scene files (JSON).
///
/// Every field is checked: wrong type, missing required field, unknown key, NaN or
/// infinite number, value out of range. A problem throws InputError naming the file
/// and the dotted field path; nothing half-loaded is returned.
#pragma once
#include <string>
#include <vector>

#include "clothlab/core/scene.h"

namespace clothlab {

/// Loads a scene file and applies command-line overrides.
/// @param path       JSON file, e.g. "scenes/spring.json"
/// @param overrides  "key=value" strings with dotted keys, e.g. "solver.dt=0.01";
///                   the value is read as JSON (number, bool, array, ...) or else as a string
/// @return           the validated scene
/// @throws InputError on any problem, naming file and field
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides = {});

/// Parses and validates a scene from JSON text (used by loadScene() and the tests).
/// @param text       the JSON document
/// @param file       file name used in error messages
/// @param overrides  as in loadScene()
/// @throws InputError on any problem
Scene parseScene(const std::string& text, const std::string& file,
                 const std::vector<std::string>& overrides = {});

}  // namespace clothlab
