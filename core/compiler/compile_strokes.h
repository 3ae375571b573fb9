// Compiling stroke emitters: each emitter's strokes become one alpha-tested
// ribbon mesh in the scene's geometry, with a RenderObject and a material.
#pragma once

#include "core/base/cancel.h"
#include "core/compiler/asset_cache.h"
#include "core/compiler/compile_counters.h"
#include "core/world/render_scene.h"

#include <span>

#include <string>
#include <vector>

namespace inkray {

// What building strokes reads and counts.
struct StrokeBuild {
  AssetCache& assets;
  CompileCounters& counters;
  Cancel cancel;
};

// Call after the scene's objects are added and before geometry.commit(). For
// each emitter with a positive count whose object was compiled (hidden objects
// grow no strokes): places, grows and meshes the strokes, appends a white
// DiffuseMaterial "<emitter>.strokes" (the strokes' vertex colours carry their
// paint; the stand-in checker when the brush image is a stand-in, asset_cache.h)
// and an object "<emitter>" whose `source` is the base object's, so
// picking a stroke picks what it was painted on. Problems are appended to
// errors as `strokes[i] "name": ...`. A scene without emitters does nothing.
// Stops early, leaving the scene unfinished, once `build.cancel` is requested.
// object_keys[o] names what shaped compiled object o (its shape and placement), so
// strokes grown on it are found again in the cache while it stays the same.
void compile_strokes(const SceneDesc& desc, RenderScene& scene, std::span<const std::string> object_keys,
                     StrokeBuild& build, std::vector<std::string>& errors);

}  // namespace inkray
