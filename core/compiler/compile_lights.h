// The lights of a compiled scene: emissive objects that can be sampled, the
// document's lights, the environment, and the distribution that picks one.
#pragma once

#include "core/world/render_scene.h"

namespace inkray {

// Fills scene.lights, scene.environment(_light), scene.light_selection and the
// objects' light indices, from scene.objects, materials and geometry (committed)
// and the document's lights and environment.
void compile_lights(const SceneDesc& desc, RenderScene& scene);

}  // namespace inkray
