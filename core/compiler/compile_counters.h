// What a SceneCompiler built over its life, by kind of work: tests assert that
// an edit ran its own stage's work and nothing else (docs/architecture.md, "Stages").
#pragma once

#include <cstdint>

namespace inkray {

struct CompileCounters {
  uint64_t compiles = 0;         // compile() calls that returned a scene
  uint64_t checks = 0;           // document checks and memory estimates
  uint64_t material_tables = 0;  // the material table was made again
  uint64_t materials = 0;        // materials compiled (the others were kept from the last table)
  uint64_t light_tables = 0;     // lights and the light selection were rebuilt
  uint64_t top_levels = 0;       // top-level BVHs committed
  uint64_t shape_bvhs = 0;       // bottom-level BVHs built (one shape each)
  uint64_t placements = 0;       // meshes moved to world space for a new transform
  uint64_t stroke_sets = 0;      // emitters whose strokes grew
  uint64_t stroke_paints = 0;    // emitters whose strokes were painted
  uint64_t files_read = 0;       // files read through the asset cache

  bool operator==(const CompileCounters&) const = default;
};

}  // namespace inkray
