// A benchmark's scene: read (and compiled), or the errors printed and the program ended.
#pragma once

#include "core/compiler/compile.h"
#include "core/document/json_io.h"

#include <cstdio>
#include <cstdlib>
#include <memory>
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

// The scene in `file` at width x height, compiled, or the compiler's error printed and
// the program ended.
inline std::shared_ptr<const RenderScene> compile_at_size_or_exit(const std::string& file, int width,
                                                                  int height) {
  SceneDesc desc = load_scene_or_exit(file);
  desc.render.width = width, desc.render.height = height;
  const CompileResult c = compile_scene(desc);
  if (!c.scene) {
    std::fprintf(stderr, "error: %s\n", c.errors.front().c_str());
    std::exit(1);
  }
  return c.scene;
}

}  // namespace inkray::bench
