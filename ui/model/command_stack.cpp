#include "ui/model/command_stack.h"

#include <utility>

namespace inkray {

void CommandStack::apply(SceneDesc& scene, SceneDesc after, std::string label, std::string merge_key,
                         Selection selection) {
  undone_.clear();
  if (merge_open_ && !merge_key.empty() && !done_.empty() && done_.back().merge_key == merge_key) {
    done_.back().after = after;
    done_.back().id = next_id_++;  // a different document from the one a save may have recorded
    scene = std::move(after);
    return;
  }
  done_.push_back({std::move(label), merge_key, scene, after, next_id_++, selection, {}});
  if (done_.size() > kMaxSteps) {
    base_id_ = done_.front().id;
    done_.erase(done_.begin());
  }
  merge_open_ = !merge_key.empty();
  scene = std::move(after);
}

bool CommandStack::undo(SceneDesc& scene, Selection* selection) {
  if (done_.empty()) return false;
  merge_open_ = false;
  scene = done_.back().before;
  if (selection) {
    done_.back().selected_after = *selection;
    *selection = done_.back().selected_before;
  }
  undone_.push_back(std::move(done_.back()));
  done_.pop_back();
  return true;
}

bool CommandStack::discard_newest(SceneDesc& scene) {
  if (done_.empty()) return false;
  merge_open_ = false;
  scene = std::move(done_.back().before);
  done_.pop_back();
  return true;
}

bool CommandStack::redo(SceneDesc& scene, Selection* selection) {
  if (undone_.empty()) return false;
  merge_open_ = false;
  scene = undone_.back().after;
  if (selection) *selection = undone_.back().selected_after;
  done_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  return true;
}

void CommandStack::clear() {
  done_.clear();
  undone_.clear();
  merge_open_ = false;
  base_id_ = next_id_++;
}

}  // namespace inkray
