#include "ui/model/selection.h"

namespace inkray {
namespace {

template <class List>
bool in_range(const List& items, int index) {
  return index >= 0 && index < int(items.size());
}

}  // namespace

bool is_valid(const SceneDesc& scene, const Selection& s) {
  switch (s.kind) {
    case ItemKind::object:
      return in_range(scene.objects, s.index);
    case ItemKind::light:
      return in_range(scene.lights, s.index);
    case ItemKind::material:
      return in_range(scene.materials, s.index);
    case ItemKind::emitter:
      return in_range(scene.strokes, s.index);
    case ItemKind::line_set:
      return in_range(scene.outlines.sets, s.index);
    default:
      return true;
  }
}

Selection validated(const SceneDesc& scene, const Selection& s) {
  return is_valid(scene, s) ? s : Selection{};
}

std::string item_name(const SceneDesc& scene, const Selection& s) {
  if (!is_valid(scene, s)) return {};
  switch (s.kind) {
    case ItemKind::none:
      return {};
    case ItemKind::camera:
      return "Camera";
    case ItemKind::render:
      return "Render settings";
    case ItemKind::environment:
      return "Environment";
    case ItemKind::outlines:
      return "Outlines";
    case ItemKind::object:
      return scene.objects[size_t(s.index)].name;
    case ItemKind::light:
      return scene.lights[size_t(s.index)].name;
    case ItemKind::material:
      return scene.materials[size_t(s.index)].name;
    case ItemKind::emitter:
      return scene.strokes[size_t(s.index)].name;
    case ItemKind::line_set:
      return scene.outlines.sets[size_t(s.index)].name;
  }
  return {};
}

}  // namespace inkray
