// The compile pipeline (docs/architecture.md, "Stages"): checks, materials,
// placed objects, strokes, crease patches, the top-level BVH, lights. Each step
// reuses what the last compile built when the document's changes leave it valid.
#include "core/compiler/compile.h"

#include "core/document/animation.h"

#include "core/compiler/compile_lights.h"
#include "core/compiler/compile_materials.h"
#include "core/compiler/compile_objects.h"
#include "core/compiler/compile_strokes.h"
#include "core/compiler/compile_view.h"
#include "core/document/memory_budget.h"
#include "core/document/scene_checks.h"
#include "core/geometry/instance_placement.h"
#include "core/npr/lines/hidden_lines.h"
#include "core/npr/outlines/line_detector.h"

#include <algorithm>
#include <map>
#include <string_view>
#include <unordered_map>

namespace inkray {
namespace {

StageSet every_stage() {
  StageSet all;
  for (int s = 1; s < kStageCount; ++s) all.add(Stage(s));
  return all;
}

// The object's overrides win over its material's where they differ from the defaults.
LineOverride combine_lines(const LineOverrideDesc& material, const LineOverrideDesc& object) {
  LineOverride l;
  l.exclude = material.exclude || object.exclude;
  l.stop_lines = material.stop_lines || object.stop_lines;
  l.width_scale = material.width_scale * object.width_scale;
  l.override_color = material.override_color || object.override_color;
  l.color = object.override_color ? object.color : material.color;
  return l;
}

// What can move while the shutter is open, the camera and the objects' transforms
// (docs/architecture.md, "Motion blur"), as the document has them at its opening and
// closing; lights, materials and the rest are read at the frame. Set only when the
// shutter is open for a time and a track changes within it. The frame's document
// carries its tracks, so it gives both.
struct Shutter {
  SceneDesc open, close;  // their camera and objects
};
SceneDesc moving_parts_at(const SceneDesc& desc, double frame) {
  SceneDesc at;
  at.camera = desc.camera;
  at.objects = desc.objects;
  for (const TrackDesc& track : desc.animation)
    if (track.target.starts_with("camera/") || track.target.starts_with("objects/"))
      at.animation.push_back(track);
  apply_animation(at, frame);
  return at;
}
std::optional<Shutter> shutter_states(const SceneDesc& desc) {
  const RenderSettings& r = desc.render;
  if (!r.motion_blur() || desc.animation.empty()) return std::nullopt;
  const double open = double(r.frame) + double(r.shutter_open),
               close = double(r.frame) + double(r.shutter_close);
  if (!animated_between(desc, open, close)) return std::nullopt;
  return Shutter{moving_parts_at(desc, open), moving_parts_at(desc, close)};
}

// What every compiled scene of the document carries whatever changed.
void set_view(const SceneDesc& desc, const std::optional<Shutter>& shutter, const LineBrushLoader& brushes,
              std::vector<std::string>& errors, RenderScene& scene) {
  scene.sampling = compile_sample_settings(desc.render);
  scene.resolve = compile_resolve_settings(desc, brushes, &errors);
  const RenderSettings& r = desc.render;
  // The frame's own instant in the shutter, which rays without a time of their own see.
  const float frame_time = r.motion_blur() ? -r.shutter_open / (r.shutter_close - r.shutter_open) : 0.f;
  scene.camera = shutter ? Camera(desc.camera, shutter->open.camera, shutter->close.camera, r.width, r.height,
                                  frame_time)
                         : Camera(desc.camera, r.width, r.height);
}

// Whether object `index` (visible at the frame) moves while the shutter is open.
bool moves(const std::optional<Shutter>& shutter, size_t index) {
  return shutter && index < shutter->open.objects.size() && index < shutter->close.objects.size() &&
         shutter->open.objects[index].transform != shutter->close.objects[index].transform;
}

// Crease lines compare smooth patches (docs/architecture.md, "Mesh normals and
// feature edges"): each document object's at the crease threshold, found only while
// crease lines are drawn. Strokes (the objects after `placed`) and spheres have none.
bool wants_crease_patches(const OutlineDesc& o) { return o.enabled && o.crease.enabled; }
bool same_crease_patches(const OutlineDesc& a, const OutlineDesc& b) {
  return wants_crease_patches(a) == wants_crease_patches(b) &&
         (!wants_crease_patches(a) || a.crease.threshold == b.crease.threshold);
}
void set_crease_patches(const OutlineDesc& outlines,
                        const std::vector<std::shared_ptr<const PlacedShape>>& placed, World& world,
                        AssetCache& assets) {
  const bool wanted = wants_crease_patches(outlines);
  for (size_t i = 0; i < world.objects.size(); ++i)
    world.objects[i].crease_patches =
        wanted && i < placed.size() ? crease_patches(*placed[i], outlines.crease.threshold, assets) : nullptr;
}

void set_bounds(World& world) {
  Point3 lo(0.f), hi(0.f);
  if (world.geometry.shape_count()) world.geometry.bounds(&lo, &hi);
  world.scene_center = 0.5f * (lo + hi);
  world.scene_radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
}

Stage stage_of(AssetKind kind) {
  switch (kind) {
    case AssetKind::mesh:
      return Stage::geometry;
    case AssetKind::brush:
      return Stage::strokes;
    case AssetKind::image:
      break;
  }
  return Stage::material;
}

// With stand-ins (`references` listed), check_scene's "file not found" for a file in
// use is no error: the compile draws a placeholder and says so in its warnings.
void forgive_missing_files(const std::vector<AssetReference>& references, std::vector<std::string>& errors) {
  for (const AssetReference& r : references) {
    if (r.exists) continue;
    const std::string prefix = r.site.at + ": ";
    std::erase_if(errors, [&](const std::string& e) { return e.starts_with(prefix); });
  }
}

// One line per file the compile drew as a placeholder: missing ones from the disk,
// unreadable ones from the failures the cache remembers.
std::vector<std::string> asset_warnings(const std::vector<AssetReference>& references, AssetCache& assets) {
  std::vector<std::string> warnings;
  for (const MissingAsset& m : missing_assets(references))
    warnings.push_back(describe(m) + ": drawn as a placeholder");
  std::vector<std::filesystem::path> reported;
  for (const AssetReference& r : references) {
    if (!r.exists || std::find(reported.begin(), reported.end(), r.resolved) != reported.end()) continue;
    const auto error = assets.failure(r.resolved);
    if (!error) continue;
    reported.push_back(r.resolved);
    std::vector<std::string> users;
    for (const AssetReference& other : references)
      if (other.resolved == r.resolved &&
          std::find(users.begin(), users.end(), other.site.user) == users.end())
        users.push_back(other.site.user);
    warnings.push_back(*error + ", used by " + users_text(users) + ": drawn as a placeholder");
  }
  return warnings;
}

}  // namespace

StageSet SceneCompiler::changed_files(const SceneDesc& desc,
                                      std::map<std::string, std::string>& stamps) const {
  StageSet changes;
  for (const AssetRef& asset : collect_assets(desc)) {
    if (asset.written.empty()) continue;
    const std::string file = (desc.base_dir / asset.written).string();
    const std::string stamp = file_stamp(file).value_or("missing");
    const auto last = file_stamps_.find(file);
    if (last != file_stamps_.end() && last->second != stamp) changes.add(stage_of(asset.kind));
    stamps[file] = stamp;
  }
  return changes;
}

CompileResult SceneCompiler::compile(const SceneDesc& document, const CompileOptions& options) {
  // An animated document is compiled as it stands at its current frame; its changes
  // are those of that picture, so a frame step moves what moved and nothing else.
  std::optional<SceneDesc> at_frame;
  if (!document.animation.empty()) at_frame = scene_at_frame(document, document.render.frame);
  const SceneDesc& desc = at_frame ? *at_frame : document;
  rest_ = nullptr;
  std::optional<SceneDesc> rest;
  if (!document.animation.empty() && !document.strokes.empty()) {
    rest = scene_at_frame(document, document.render.frame_start);
    rest_ = &*rest;
  }
  assets_.serve_stand_ins(options.stand_in_for_missing_assets);
  if (!options.stand_in_for_missing_assets) return compile_world(desc, options, {});
  const std::vector<AssetReference> references = list_asset_references(desc);
  CompileResult result = compile_world(desc, options, references);
  if (result.cancelled) return result;
  std::vector<std::string> files = asset_warnings(references, assets_);
  if (files != asset_warnings_) result.warnings.insert(result.warnings.end(), files.begin(), files.end());
  asset_warnings_ = std::move(files);
  return result;
}

CompileResult SceneCompiler::compile_world(const SceneDesc& desc, const CompileOptions& options,
                                           const std::vector<AssetReference>& references) {
  CompileResult result;
  result.changes = last_desc_ ? changed_stages(*last_desc_, desc) : every_stage();
  // A file edited on disk is a change the document cannot show.
  std::map<std::string, std::string> stamps;
  const StageSet file_changes = changed_files(desc, stamps);
  result.changes.add(file_changes);
  const auto cancelled = [&] {
    if (!options.cancel.requested()) return false;
    result.cancelled = true;
    result.scene.reset();
    result.errors = {"cancelled while building the scene"};
    return true;
  };
  // The editor holds documents that cannot render yet (an unset file, a dangling name):
  // they stop here with the reader's messages rather than deeper with vaguer ones.
  assets_.begin_compile();
  ErrorLog log("");
  // The last document compiled had no problem: with the same names and no file
  // changed on disk, only the items the edit changed can have one
  // (docs/architecture.md, "Checks of an edit").
  std::optional<CheckScope> scope;
  if (last_desc_ && file_changes.empty() && same_names(*last_desc_, desc))
    scope = changed_items(*last_desc_, desc);
  check_scene(desc, desc.base_dir, log, scope ? &*scope : nullptr);
  result.errors = log.take();
  forgive_missing_files(references, result.errors);
  if (result.errors.empty())
    check_memory_budget(desc, options.memory_limit, result.errors,
                        [&](const std::filesystem::path& file, std::string* error) {
                          return assets_.image_size(file, error);
                        });
  ++counters_.checks;
  counters_.files_read = assets_.files_read();
  if (!result.errors.empty()) return result;
  const std::optional<Shutter> shutter = shutter_states(desc);
  const LineBrushLoader brushes = [&](const StrokeEmitterDesc& brush, std::string* error) {
    return std::shared_ptr<const AlphaTexture>(assets_.brush(brush, desc.base_dir, error));
  };

  const auto remember = [&](std::shared_ptr<RenderScene> scene, size_t document_materials) {
    scene->lines =
        make_line_setup(desc.outlines, *scene);  // reads the world's bounds, so once it is in place
    // Hidden lines are found on the world's surfaces from this view's camera.
    const auto& sets = scene->resolve.sets;
    if (scene->lines.active &&
        std::any_of(sets.begin(), sets.end(), [](const LineSet& s) { return s.select.hidden; })) {
      scene->resolve.hidden =
          std::make_shared<const std::vector<Chain>>(hidden_chains(*scene, options.cancel));
      scene->resolve.hidden_width = scene->sampling.width;
    }
    last_desc_ = desc;
    last_ = scene;
    last_document_materials_ = document_materials;
    file_stamps_ = std::move(stamps);
    result.scene = std::move(scene);
    ++counters_.compiles;
    counters_.files_read = assets_.files_read();
  };
  if (last_ && result.changes.within({Stage::layout, Stage::limits, Stage::resolve, Stage::camera,
                                      Stage::sampling, Stage::film})) {
    // Nothing of the world changed: a new view of the same one, with the crease
    // patches of a new threshold.
    auto scene = std::make_shared<RenderScene>(*last_);
    set_view(desc, shutter, brushes, result.errors, *scene);
    if (!result.errors.empty()) return result;
    if (!same_crease_patches(last_desc_->outlines, desc.outlines)) {
      auto world = std::make_shared<World>(*last_->world);
      set_crease_patches(desc.outlines, placed_, *world, assets_);
      scene->world = std::move(world);
    }
    remember(std::move(scene), last_document_materials_);
    return result;
  }

  auto scene = std::make_shared<RenderScene>();
  set_view(desc, shutter, brushes, result.errors, *scene);
  if (!result.errors.empty()) return result;
  auto world = std::make_shared<World>();
  std::vector<std::vector<std::string>> material_keys = material_keys_;
  if (!last_ || result.changes.has(Stage::material)) {
    // Only the materials whose description changed are compiled again.
    std::vector<Material> last_table;
    if (last_)
      last_table.assign(last_->world->materials.begin(),
                        last_->world->materials.begin() + std::ptrdiff_t(last_document_materials_));
    // An image changed on disk (or appeared) is seen only by compiling its materials again.
    LastMaterials previous;
    if (last_desc_ && !file_changes.has(Stage::material))
      previous = {&last_desc_->materials, &last_table, &material_keys_};
    counters_.materials += compile_materials(desc, *world, result.errors, assets_, material_keys, previous,
                                             options.stand_in_for_broken_graphs ? &result.warnings : nullptr);
    ++counters_.material_tables;
  } else {
    for (const auto& keys : material_keys_)
      assets_.touch(keys);  // the images the reused table holds stay cached
    world->materials.assign(last_->world->materials.begin(),
                            last_->world->materials.begin() + std::ptrdiff_t(last_document_materials_));
    world->material_names.assign(
        last_->world->material_names.begin(),
        last_->world->material_names.begin() + std::ptrdiff_t(last_document_materials_));
  }
  const size_t document_materials = world->materials.size();
  std::map<std::string, uint32_t> material_index;
  for (size_t i = 0; i < world->material_names.size(); ++i)
    material_index[world->material_names[i]] = uint32_t(i);

  if (!shutter && reuse_objects(desc, result.changes, file_changes.has(Stage::geometry),
                                options.stand_in_for_missing_assets, *world)) {
    compile_lights(desc, *world);
    ++counters_.light_tables;
    // No finish_compile(): the shapes of the objects that stayed were not looked up, and
    // the next compile that places every object drops what neither uses.
    material_keys_ = std::move(material_keys);
    scene->world = std::move(world);
    remember(std::move(scene), document_materials);
    return result;
  }

  ObjectBuild objects{assets_, counters_, desc.base_dir, options.stand_in_for_missing_assets};
  std::vector<StrokeAnchor> anchors;
  std::vector<std::shared_ptr<const PlacedShape>> placed_objects;
  // Placements of the last compile, by document object, serve objects whose shape and
  // transform are as they were while no mesh file changed on disk: a move of one object
  // of thousands places one (docs/architecture.md, "Stages").
  std::vector<Placement> placements(desc.objects.size());
  const bool reuse_placements = last_desc_ && !file_changes.has(Stage::geometry) &&
                                last_desc_->base_dir == desc.base_dir &&
                                last_stand_ins_ == options.stand_in_for_missing_assets;
  std::vector<std::string> reused_keys;
  // The material an object's line overrides come from: the first of its name.
  std::unordered_map<std::string_view, size_t> first_material;
  for (size_t m = desc.materials.size(); m-- > 0;) first_material[desc.materials[m].name] = m;
  for (size_t i = 0; i < desc.objects.size(); ++i) {
    if ((i & 255) == 0 && cancelled()) return result;
    const ObjectDesc& obj = desc.objects[i];
    if (!obj.visible) continue;
    const auto where = [&] { return "objects[" + std::to_string(i) + "] \"" + obj.name + "\": "; };
    const auto mat = material_index.find(obj.material);
    if (mat == material_index.end()) {
      result.errors.push_back(where() + "no material named \"" + obj.material + "\"");
      continue;
    }
    const Transform to_world = transform_from_desc(obj.transform);
    // At a frame where its scale is zero (an animated flip) an object that stands still
    // is not there: no surface, light or strokes. One that moves is traced over the rest
    // of the shutter (docs/architecture.md, "Singular transforms").
    if (!placeable(to_world) &&
        (!moves(shutter, i) || motion_pieces(transform_from_desc(shutter->open.objects[i].transform),
                                             transform_from_desc(shutter->close.objects[i].transform))
                                   .empty()))
      continue;
    std::string key, error;
    std::shared_ptr<const PlacedShape> placed;
    if (reuse_placements && i < placements_.size() && placements_[i].placed &&
        last_desc_->objects[i].shape == obj.shape && last_desc_->objects[i].transform == obj.transform) {
      placed = placements_[i].placed;
      key = placements_[i].key;
      reused_keys.push_back(key);
    } else {
      placed = place_object(obj, objects, &key, &error);
    }
    if (!placed) {
      result.errors.push_back(where() + error);
      continue;
    }
    if (!placed->problem.empty()) {
      result.errors.push_back(where() + placed->problem);
      continue;
    }
    placements[i] = {key, placed};
    if (moves(shutter, i)) {
      // Traced where it stands at each ray's instant; lights and strokes read it at
      // the frame (docs/architecture.md, "Motion blur").
      const MovingShape moving = place_moving(obj, *placed, shutter->open.objects[i].transform,
                                              shutter->close.objects[i].transform, objects);
      if (!moving.problem.empty()) {
        result.errors.push_back(where() + "while the shutter is open, " + moving.problem);
        continue;
      }
      world->geometry.add_moving(moving.bvh, moving.open, moving.close, nullptr, placed->world);
    } else {
      world->geometry.add(placed->bvh, placed->to_world, placed->world);
    }
    world->objects.push_back({obj.name, mat->second, -1, uint32_t(i), mat->second,
                              combine_lines(desc.materials[first_material[obj.material]].lines, obj.lines),
                              Transform{to_world.inv, to_world.m}, Transform{}});
    anchors.push_back(stroke_anchor(obj, i, *placed, std::move(key), objects));
    if (!anchors.back().world) {
      result.errors.push_back(where() + "cannot be placed as it stands at frame " +
                              std::to_string(desc.render.frame_start) + ", where its strokes grow");
      continue;
    }
    if (moves(shutter, i)) {
      // Strokes grown at rest ride along: from rest to the object's own space, then
      // out again as it stands at the shutter's opening and closing.
      StrokeAnchor& anchor = anchors.back();
      anchor.moving = true;
      anchor.rest_to_open = transform_from_desc(shutter->open.objects[i].transform) * anchor.to_object;
      anchor.rest_to_close = transform_from_desc(shutter->close.objects[i].transform) * anchor.to_object;
    }
    placed_objects.push_back(placed);
  }
  if (!result.errors.empty()) return result;
  assets_.touch(reused_keys);
  // Strokes grow on the compiled objects and join the same BVH.
  if (cancelled()) return result;
  StrokeBuild strokes{assets_, counters_, options.cancel};
  compile_strokes(desc, *world, anchors, strokes, result.errors);
  if (cancelled() || !result.errors.empty()) return result;
  set_crease_patches(desc.outlines, placed_objects, *world, assets_);
  // Objects that moved, appeared or changed shape need a new top level; else the
  // last one serves (a material edit).
  if (last_ && world->geometry.same_instances(last_->world->geometry)) {
    world->geometry = last_->world->geometry;
  } else {
    world->geometry.commit(last_ ? &last_->world->geometry : nullptr);
    ++counters_.top_levels;
  }

  set_bounds(*world);
  compile_lights(desc, *world);
  ++counters_.light_tables;

  assets_.finish_compile();
  material_keys_ = std::move(material_keys);
  placed_ = std::move(placed_objects);
  placements_ = std::move(placements);
  last_stand_ins_ = options.stand_in_for_missing_assets;
  scene->world = std::move(world);
  remember(std::move(scene), document_materials);
  return result;
}

bool SceneCompiler::reuse_objects(const SceneDesc& desc, StageSet changes, bool files_changed, bool stand_ins,
                                  World& world) {
  // Strokes are painted from their objects' materials and grow on their shapes, so a
  // scene with emitters takes the whole pass, as does one whose files changed on disk.
  if (!last_ || changes.has(Stage::geometry) || changes.has(Stage::strokes) || files_changed || rest_ ||
      !desc.strokes.empty() || !last_desc_->strokes.empty() || last_->world->geometry.any_moving() ||
      stand_ins != last_stand_ins_ || desc.base_dir != last_desc_->base_dir ||
      desc.objects.size() != last_desc_->objects.size() ||
      last_document_materials_ != last_->world->materials.size() ||
      world.material_names != last_->world->material_names)
    return false;
  // The compiled object of each document object (-1: hidden or not placeable then).
  std::vector<int> compiled(desc.objects.size(), -1);
  for (size_t o = 0; o < last_->world->objects.size(); ++o)
    compiled[last_->world->objects[o].source] = int(o);
  struct Move {
    size_t object;
    std::string key;
    std::shared_ptr<const PlacedShape> placed;
  };
  std::vector<Move> moves;
  if (changes.has(Stage::object)) {
    ObjectBuild build{assets_, counters_, desc.base_dir, stand_ins};
    for (size_t i = 0; i < desc.objects.size(); ++i) {
      const ObjectDesc& before = last_desc_->objects[i];
      const ObjectDesc& after = desc.objects[i];
      if (before == after) continue;
      // Only a new transform (and line overrides, read below for every object) is
      // handled here; a renamed, hidden or re-materialled object takes the whole pass.
      ObjectDesc same = after;
      same.transform = before.transform;
      same.lines = before.lines;
      if (!(same == before) || compiled[i] < 0 || moves.size() == kMostMovedObjects) return false;
      if (before.transform == after.transform) continue;
      // Placed before anything changes: an object that cannot be placed leaves the
      // whole pass to report it.
      if (!placeable(transform_from_desc(after.transform))) return false;
      std::string key, error;
      auto placed = place_object(after, build, &key, &error);
      if (!placed || !placed->problem.empty()) return false;
      moves.push_back({i, std::move(key), std::move(placed)});
    }
  }
  world.objects = last_->world->objects;
  world.geometry =
      moves.empty() ? last_->world->geometry : EmbreeScene::with_instances_of(last_->world->geometry);
  const bool creases = wants_crease_patches(desc.outlines);
  for (Move& m : moves) {
    const auto index = uint32_t(compiled[m.object]);
    RenderObject& o = world.objects[index];
    const Transform to_world = transform_from_desc(desc.objects[m.object].transform);
    o.to_object = Transform{to_world.inv, to_world.m};
    o.crease_patches = creases ? crease_patches(*m.placed, desc.outlines.crease.threshold, assets_) : nullptr;
    world.geometry.replace(index, m.placed->bvh, m.placed->to_world, m.placed->world);
    placed_[index] = m.placed;
    // The placement it leaves is dropped, so a drag does not pile up world-space copies.
    if (placements_[m.object].key != m.key) assets_.drop(placements_[m.object].key);
    placements_[m.object] = {std::move(m.key), std::move(m.placed)};
  }
  for (RenderObject& o : world.objects)
    o.lines = combine_lines(desc.materials[o.material].lines, desc.objects[o.source].lines);
  if (!same_crease_patches(last_desc_->outlines, desc.outlines))
    set_crease_patches(desc.outlines, placed_, world, assets_);
  if (moves.empty()) {
    world.scene_center = last_->world->scene_center;
    world.scene_radius = last_->world->scene_radius;
  } else {
    world.geometry.commit(&last_->world->geometry);
    ++counters_.top_levels;
    set_bounds(world);
  }
  return true;
}

StrokeAnchor SceneCompiler::stroke_anchor(const ObjectDesc& obj, size_t index, const PlacedShape& placed,
                                          std::string key, ObjectBuild& build) const {
  const Transform now = transform_from_desc(obj.transform);
  const ObjectDesc* rest = rest_ && index < rest_->objects.size() ? &rest_->objects[index] : nullptr;
  if (!rest || rest->transform == obj.transform) {
    return {std::move(key), placed.world, Transform{now.inv, now.m}, Transform{}};
  }
  std::string rest_key, error;
  const auto at_rest = place_object(*rest, build, &rest_key, &error);
  if (!at_rest || !at_rest->problem.empty()) return {};
  const Transform then = transform_from_desc(rest->transform);
  return {std::move(rest_key), at_rest->world, Transform{then.inv, then.m},
          now * Transform{then.inv, then.m}};
}

CompileResult compile_scene(const SceneDesc& desc, const CompileOptions& options) {
  return SceneCompiler().compile(desc, options);
}

}  // namespace inkray
