// Structural edits of the scene document as pure functions: each takes a
// SceneDesc and returns the edited copy, which the caller hands to
// Document::edit so it becomes one undoable step. References by name
// (object -> material, emitter -> object) are kept consistent.
#pragma once

#include "ui/selection.h"

#include <string>
#include <string_view>

namespace inkray {

// `base` if no item of that kind uses it, else "base.1", "base.2", ...
std::string unique_name(const SceneDesc& scene, ItemKind kind, std::string_view base);

enum class NewShape { sphere, quad, box };
// Each returns the new item's selection; the scene gains a default material when needed.
Selection add_shape(SceneDesc& scene, NewShape shape);
Selection add_mesh(SceneDesc& scene, const std::string& obj_path);
Selection add_point_light(SceneDesc& scene);
Selection add_stroke_emitter(SceneDesc& scene, const std::string& object);
Selection add_material(SceneDesc& scene);

Selection duplicate_item(SceneDesc& scene, const Selection& item);
// Deleting an object also deletes the stroke emitters growing on it.
bool delete_item(SceneDesc& scene, const Selection& item);
// Fails (returns false) when the name is empty or taken.
bool rename_item(SceneDesc& scene, const Selection& item, const std::string& name);
bool set_visible(SceneDesc& scene, const Selection& item, bool visible);

// The world-space bounds of an object's shape after its transform (meshes use a unit box).
void object_bounds(const ObjectDesc& object, Point3* center, float* radius);

}  // namespace inkray
