// The lights of a compiled scene: emissive objects that can be sampled, the
// document's lights, the environment, and the distribution that picks one.
#pragma once

#include "core/document/desc.h"
#include "core/world/render_scene.h"

namespace inkray {

// Fills world.lights, world.environment(_light), world.light_selection and the
// objects' light indices, from world.objects, materials and geometry (committed)
// and the document's lights and environment.
void compile_lights(const SceneDesc& desc, World& world);

}  // namespace inkray
