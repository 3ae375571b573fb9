// Compiling stroke emitters: each emitter's strokes become one alpha-tested
// ribbon mesh in the scene's geometry, with a RenderObject and a material.
#pragma once

#include "core/base/cancel.h"
#include "core/compiler/asset_cache.h"
#include "core/compiler/compile_counters.h"
#include "core/document/desc.h"
#include "core/world/render_scene.h"

#include <span>

#include <string>
#include <vector>

namespace inkray {

// Where an object's strokes grow: the object as it stands at the shot's first frame (its
// rest), so an animated object keeps the same strokes on the same places of its surface
// at every frame (docs/architecture.md, "Animation"). For an object that does not move,
// rest is where it is and rest_to_now the identity.
struct StrokeAnchor {
  std::string key;                     // what shaped the object at rest (shape and placement)
  std::shared_ptr<const Shape> world;  // the object at rest, in world space
  Transform to_object;                 // world -> object at rest (texture lookups of the paint)
  Transform rest_to_now;               // carries strokes grown at rest to the object's place now
  // Whether the object moves while the shutter is open (docs/architecture.md, "Motion
  // blur"): its strokes are then carried by rest_to_open at the shutter's opening and
  // by rest_to_close at its closing.
  bool moving = false;
  Transform rest_to_open{}, rest_to_close{};
};

// What building strokes reads and counts.
struct StrokeBuild {
  AssetCache& assets;
  CompileCounters& counters;
  Cancel cancel;
};

// Call after the scene's objects are added and before geometry.commit(). For
// each emitter with a positive count whose object was compiled (hidden objects
// grow no strokes): places, grows and meshes the strokes (or finds them grown: a new
// brush is only a new texture for their alpha test, placed with them), appends a white
// DiffuseMaterial "<emitter>.strokes" (the strokes' vertex colours carry their
// paint; the stand-in checker when the brush image is a stand-in, asset_cache.h)
// and an object "<emitter>" whose `source` is the base object's, so
// picking a stroke picks what it was painted on. Problems are appended to
// errors as `strokes[i] "name": ...`. A scene without emitters does nothing.
// Stops early, leaving the scene unfinished, once `build.cancel` is requested.
// anchors[o] says where compiled object o's strokes grow; its key finds them again in
// the cache while the object's rest stays the same.
void compile_strokes(const SceneDesc& desc, World& world, std::span<const StrokeAnchor> anchors,
                     StrokeBuild& build, std::vector<std::string>& errors);

}  // namespace inkray
