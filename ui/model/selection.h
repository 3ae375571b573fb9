// What the user has selected: one item of the document, by kind and index.
#pragma once

#include "core/document/desc.h"

#include <string>

namespace inkray {

// A line set (outlines.sets) is an item of its own: the Line sets panel edits it by the
// same paths as the rest (ui/panels/line_sets_panel.h), and its tracks follow its name.
enum class ItemKind {
  none,
  camera,
  render,
  environment,
  outlines,
  object,
  light,
  material,
  emitter,
  line_set
};

struct Selection {
  ItemKind kind = ItemKind::none;
  int index = -1;  // into the document's list of that kind; unused for singletons
  bool operator==(const Selection&) const = default;
};

// The item still exists in the document (after an undo or a delete it may not).
bool is_valid(const SceneDesc& scene, const Selection& selection);
// The selection if valid, else nothing.
Selection validated(const SceneDesc& scene, const Selection& selection);
// The item's name as the scene graph shows it.
std::string item_name(const SceneDesc& scene, const Selection& selection);

}  // namespace inkray
