// A benchmark's scene: read, or the reader's errors printed and the program ended.
#pragma once

#include "core/document/json_io.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace inkray::bench {

inline SceneDesc load_scene_or_exit(const std::string& file) {
  const SceneLoadResult loaded = load_scene(file);
  if (!loaded) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    std::exit(1);
  }
  return *loaded.scene;
}

}  // namespace inkray::bench
