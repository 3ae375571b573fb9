// Compiling stroke emitters: each emitter's strokes become one alpha-tested
// ribbon mesh in the scene's geometry, with a RenderObject and a material.
#pragma once

#include "core/base/cancel.h"
#include "core/world/render_scene.h"

#include <string>
#include <vector>

namespace inkray {

// Call after the scene's objects are added and before geometry.commit(). For
// each emitter with a positive count whose object was compiled (hidden objects
// grow no strokes): places, grows and meshes the strokes, appends a white
// DiffuseMaterial "<emitter>.strokes" (the strokes' vertex colours carry their
// paint) and an object "<emitter>" whose `source` is the base object's, so
// picking a stroke picks what it was painted on. Problems are appended to
// errors as `strokes[i] "name": ...`. A scene without emitters does nothing.
// Stops early, leaving the scene unfinished, once `cancel` is requested.
void compile_strokes(const SceneDesc& desc, RenderScene& scene, std::vector<std::string>& errors,
                     const Cancel& cancel = {});

}  // namespace inkray
