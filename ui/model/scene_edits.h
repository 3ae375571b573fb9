// Structural edits of the scene document as pure functions: each takes a
// SceneDesc and returns the edited copy, which the caller hands to
// Document::edit so it becomes one undoable step. References by name
// (object -> material, emitter -> object) and animation tracks are kept consistent.
#pragma once

#include "ui/model/selection.h"

#include <string>
#include <string_view>

namespace inkray {

// `base` if no item of that kind uses it, else "base.1", "base.2", ...
std::string unique_name(const SceneDesc& scene, ItemKind kind, std::string_view base);

enum class NewShape { sphere, quad, box };
// Each returns the new item's selection; the scene gains a default material when needed.
// Shapes and lights are placed in front of the camera, sized to the view (ui/model/placement.h).
Selection add_shape(SceneDesc& scene, NewShape shape);
// The mesh is read (its bounds) and fitted to the view, unless `keep_native_size`: then it
// keeps the size and place its file gives it. An unreadable file is placed unscaled at
// the view's centre; compiling the scene reports what is wrong with it.
Selection add_mesh(SceneDesc& scene, const std::string& obj_path, bool keep_native_size = false);
Selection add_point_light(SceneDesc& scene);
Selection add_stroke_emitter(SceneDesc& scene, const std::string& object);
Selection add_material(SceneDesc& scene);

// The copy gets copies of the item's tracks.
Selection duplicate_item(SceneDesc& scene, const Selection& item);
// Deleting an object also deletes the stroke emitters growing on it; tracks go with
// what they animate.
bool delete_item(SceneDesc& scene, const Selection& item);
// Fails (returns false) when the name is empty or taken. The item's tracks follow the name.
bool rename_item(SceneDesc& scene, const Selection& item, const std::string& name);

// The animation path (core/document/animation.h) of a parameter of the selected item:
// key_path(scene, ball, "transform.translate") is "objects/ball/transform/translate";
// groups are joined by '.' or '/'. Without a parameter, the start every path of the
// item's own parameters shares ("objects/ball/", "camera/"); "" for no selection.
// The timeline, the widgets and the keys all name parameters through it.
std::string key_path(const SceneDesc& scene, const Selection& item, std::string_view param = {});
bool set_visible(SceneDesc& scene, const Selection& item, bool visible);

// The bounds of an object's shape before its transform (meshes: a unit box about the
// origin, since their extent is in the OBJ file).
void local_bounds(const ObjectDesc& object, Point3* lo, Point3* hi);
// The axis-aligned world-space box around the local bounds after the transform.
void object_box(const ObjectDesc& object, Point3* lo, Point3* hi);
// The same as a centre and the radius of a sphere around the box.
void object_bounds(const ObjectDesc& object, Point3* center, float* radius);

}  // namespace inkray
