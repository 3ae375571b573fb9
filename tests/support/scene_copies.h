// An example scene copied alone into a test's folder, so every mesh, texture and brush
// it names is missing there: the data is the shipped scenes, not shaped for a test.
#pragma once

#include "core/document/json_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace inkray::testing {

// scenes/`name` copied into `folder` and read for editing (missing files are warnings).
inline SceneDesc example_scene_alone(const std::filesystem::path& folder, const std::string& name) {
  const std::filesystem::path scenes = INKRAY_SOURCE_DIR "/scenes";
  std::filesystem::copy_file(scenes / name, folder / name);
  SceneLoadResult loaded = load_scene(folder / name, ReadFor::editing);
  EXPECT_TRUE(loaded) << (loaded.errors.empty() ? "" : loaded.errors.front());
  return loaded ? *loaded.scene : SceneDesc{};
}

}  // namespace inkray::testing
