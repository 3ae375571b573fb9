// Reads a parsed scene document into a SceneDesc through the parameter tables,
// checking every value against its Param and the references between sections.
// Every problem goes to the log; none stops the reading.
#pragma once

#include "core/base/cancel.h"
#include "core/document/desc.h"
#include "core/document/error_log.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace inkray {

// Finishes with name_unnamed and check_scene (scene_checks.h): asset paths are checked
// to name regular files relative to base_dir.
// Stops between list items once `cancel` is requested, logging kCancelledReading.
void read_scene_document(const nlohmann::json& doc, const std::filesystem::path& base_dir, SceneDesc& scene,
                         ErrorLog& log, const Cancel& cancel = {});

}  // namespace inkray
