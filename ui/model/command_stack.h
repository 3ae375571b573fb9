// Undo/redo over the scene document. Each step keeps the whole SceneDesc
// before and after it: snapshots share every item the step did not change
// (core/base/shared_list.h), meshes and strokes live outside the document, and
// whole snapshots make every edit undoable with one mechanism.
#pragma once

#include "core/document/desc.h"
#include "ui/model/selection.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace inkray {

class CommandStack {
 public:
  static constexpr std::size_t kMaxSteps = 256;

  // Sets scene = after and records the step. While merging is open, a step with
  // the same non-empty merge key as the previous one extends it instead, so a
  // slider drag becomes one undo step; end_merge() closes it. `selection` is what was
  // selected before the step: undoing it selects that again (a deleted item comes back
  // selected), and redoing it selects what was selected when it was undone.
  void apply(SceneDesc& scene, SceneDesc after, std::string label, std::string merge_key = {},
             Selection selection = {});
  void end_merge() { merge_open_ = false; }

  bool undo(SceneDesc& scene, Selection* selection = nullptr);
  // Takes back the newest step as if it was never made (no redo entry): a gesture the
  // user cancelled with Esc. False when there is none.
  bool discard_newest(SceneDesc& scene);
  bool redo(SceneDesc& scene, Selection* selection = nullptr);
  bool can_undo() const { return !done_.empty(); }
  bool can_redo() const { return !undone_.empty(); }
  std::string undo_label() const { return done_.empty() ? std::string() : done_.back().label; }
  std::string redo_label() const { return undone_.empty() ? std::string() : undone_.back().label; }
  std::size_t size() const { return done_.size(); }

  // Names the document's current state: equal ids mean equal documents, so a
  // document is unsaved when this differs from the id recorded at its save.
  uint64_t state_id() const { return done_.empty() ? base_id_ : done_.back().id; }
  void clear();

 private:
  struct Step {
    std::string label;
    std::string merge_key;
    SceneDesc before, after;
    uint64_t id = 0;
    Selection selected_before, selected_after;
  };
  std::vector<Step> done_, undone_;
  bool merge_open_ = false;
  uint64_t next_id_ = 1;
  uint64_t base_id_ = 0;  // the state below the oldest kept step
};

}  // namespace inkray
