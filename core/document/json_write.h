// Writes a SceneDesc as JSON through the same parameter tables the reader uses:
// every field, defaults included, in declaration order, so files are explicit; only
// unset optional names and paths are left out (the reader takes absent as unset).
#pragma once

#include "core/document/desc.h"

#include <nlohmann/json.hpp>

#include <string>

namespace inkray {

// Ordered so files read top-down: format, version, camera, render, environment,
// materials, objects, lights; within a struct, its parameter table's order.
nlohmann::ordered_json write_scene_document(const SceneDesc& scene);

// Pretty-prints with a 2-space indent, keeping arrays of plain values on one line
// ("albedo": [0.8, 0.8, 0.8]) so files stay short enough to read and diff.
std::string format_scene_json(const nlohmann::ordered_json& doc);

// The double nearest the shortest decimal that reads back as f, so files say 0.8
// rather than 0.800000011920929 and still load to the identical float.
double float_to_json_number(float f);

}  // namespace inkray
