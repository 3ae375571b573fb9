// Compiling: SceneDesc -> immutable RenderScene (BVHs, flat materials,
// light-sampling tables). A SceneCompiler keeps what it built between compiles
// and redoes only what the document's changes touched (docs/architecture.md,
// "Stages"); compile_scene is a compile without a past. Errors name the object
// or material.
#pragma once

#include "core/base/cancel.h"
#include "core/compiler/asset_cache.h"
#include "core/compiler/compile_counters.h"
#include "core/document/asset_relink.h"
#include "core/document/stage_diff.h"
#include "core/world/render_scene.h"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace inkray {

struct PlacedShape;
struct ObjectBuild;
struct StrokeAnchor;

struct CompileOptions {
  Cancel cancel;                   // checked between objects and inside stroke building
  std::uint64_t memory_limit = 0;  // bytes the estimate may reach; 0: half the machine's memory
  // Draw a material graph that does not compile in a loud stand-in colour and report
  // it in `warnings`, rather than failing the compile (the editor: the scene stays usable).
  bool stand_in_for_broken_graphs = false;
  // Draw what a missing or unreadable file would have given as a placeholder and
  // report the file in `warnings`, rather than failing the compile (the editor: a
  // scene whose files moved opens and can be relinked). A texture or brush image
  // becomes a magenta checker (stand_in_image(), asset_cache.h), a mesh a unit box
  // under the object's transform.
  bool stand_in_for_missing_assets = false;
};

struct CompileResult {
  std::shared_ptr<const RenderScene> scene;  // null when there were errors or it was cancelled
  std::vector<std::string> errors;
  // Broken graphs and missing or unreadable files drawn as stand-ins; the scene
  // renders. A SceneCompiler repeats the files' warnings only when they change, so
  // an editor that logs them is not told again on every edit.
  std::vector<std::string> warnings;
  bool cancelled = false;  // stopped by options.cancel; errors then says so
  // What separates this document from the last one compiled; every stage for a first compile.
  StageSet changes;
};

class SceneCompiler {
 public:
  // Runs check_scene first (a document read for editing may not render yet). Before
  // anything large is allocated the scene's memory estimate is checked against the
  // limit (memory_budget.h); transformed geometry must lie within kMaxWorldCoordinate
  // of the origin. What the last successful compile built is reused where the
  // document's changes leave it valid.
  // An animated document is compiled at its render.frame (document/animation.h).
  CompileResult compile(const SceneDesc& desc, const CompileOptions& options = {});

  const CompileCounters& counters() const { return counters_; }
  AssetCache& assets() { return assets_; }

 private:
  // Stages of the asset files whose stamps differ from the last compile's; fills
  // `stamps` with the current ones.
  StageSet changed_files(const SceneDesc& desc, std::map<std::string, std::string>& stamps) const;
  // The compile itself; `references` (listed only for stand-ins) are the files in use.
  CompileResult compile_world(const SceneDesc& desc, const CompileOptions& options,
                              const std::vector<AssetReference>& references);

  // The objects and top level of last_ for `world` (compiled up to its materials), with
  // the objects whose transforms changed placed anew, when the edit `changes` touched
  // nothing else of the objects (a material, light or transform edit) and none of
  // them moves while the shutter is open. False, leaving `world` as it was, when the
  // whole object pass is needed.
  bool reuse_objects(const SceneDesc& desc, StageSet changes, bool files_changed, bool stand_ins,
                     World& world);
  // More moved objects than this take the whole object pass.
  static constexpr size_t kMostMovedObjects = 64;
  // Where object `index`'s strokes grow: its place at the shot's first frame.
  StrokeAnchor stroke_anchor(const ObjectDesc& obj, size_t index, const PlacedShape& placed, std::string key,
                             ObjectBuild& build) const;

  AssetCache assets_;
  CompileCounters counters_;
  const SceneDesc* rest_ = nullptr;     // the document at frame_start, while a compile of strokes needs it
  std::optional<SceneDesc> last_desc_;  // the document last_ was compiled from
  std::shared_ptr<const RenderScene> last_;
  size_t last_document_materials_ = 0;  // last_->world->materials before the stroke materials
  std::vector<std::vector<std::string>> material_keys_;  // per material: the cache entries it was built from
  std::map<std::string, std::string> file_stamps_;       // asset file -> stamp, at the last compile
  // The placed shapes of last_'s document objects (its first objects), whose crease
  // patches a new crease threshold recomputes without recompiling the world.
  std::vector<std::shared_ptr<const PlacedShape>> placed_;
  std::vector<std::string> asset_warnings_;  // the missing and unreadable files last reported
  // Where the last compile placed each document object (null where it placed none),
  // and the cache key of that placement: an object whose shape and transform stay is
  // placed the same again.
  struct Placement {
    std::string key;
    std::shared_ptr<const PlacedShape> placed;
  };
  std::vector<Placement> placements_;
  bool last_stand_ins_ = false;  // CompileOptions::stand_in_for_missing_assets of that compile
};

CompileResult compile_scene(const SceneDesc& desc, const CompileOptions& options = {});

// Geometry beyond this distance from the origin is refused: far inside the ray
// origins Embree accepts (about 1.8e18), since a ray can start on any surface.
inline constexpr float kMaxWorldCoordinate = 1e15f;

}  // namespace inkray
