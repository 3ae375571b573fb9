// compile_scene: SceneDesc -> immutable RenderScene (Embree BVH, flat
// materials, light-sampling tables). Errors name the object or material.
#pragma once

#include "core/base/cancel.h"
#include "core/world/render_scene.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace inkray {

struct CompileOptions {
  Cancel cancel;                  // checked between objects and inside stroke building
  std::uint64_t memory_limit = 0;  // bytes the estimate may reach; 0: half the machine's memory
};

struct CompileResult {
  std::shared_ptr<const RenderScene> scene;  // null when there were errors or it was cancelled
  std::vector<std::string> errors;
  bool cancelled = false;  // stopped by options.cancel; errors then says so
};

// Runs check_scene first (a document read for editing may not render yet). Before
// anything large is allocated the scene's memory estimate is checked against the
// limit (memory_budget.h); transformed geometry must lie within kMaxWorldCoordinate
// of the origin.
CompileResult compile_scene(const SceneDesc& desc, const CompileOptions& options = {});

// Geometry beyond this distance from the origin is refused: far inside the ray
// origins Embree accepts (about 1.8e18), since a ray can start on any surface.
inline constexpr float kMaxWorldCoordinate = 1e15f;

// Scale, then the rotations in order, then translation.
Transform transform_from_desc(const TransformDesc& desc);

}  // namespace inkray
