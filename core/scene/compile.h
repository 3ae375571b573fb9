// compile_scene: SceneDesc -> immutable RenderScene (Embree BVH, flat
// materials, light-sampling tables). Errors name the object or material.
#pragma once

#include "core/scene/render_scene.h"

#include <memory>
#include <string>
#include <vector>

namespace inkray {

struct CompileResult {
  std::shared_ptr<const RenderScene> scene;  // null when there were errors
  std::vector<std::string> errors;
};

CompileResult compile_scene(const SceneDesc& desc);

// Scale, then the rotations in order, then translation.
Transform transform_from_desc(const TransformDesc& desc);

}  // namespace inkray
