// The open scene document: its SceneDesc, file, undo history and unsaved
// state. Every change goes through edit(), so every change can be undone; the one
// exception is the current frame (set_frame), which, as in Blender, is where the user
// looks rather than what the document says, and which undo leaves where it is.
#pragma once

#include "core/document/json_io.h"
#include "ui/model/command_stack.h"

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

class Document {
 public:
  Document();

  // What File > New opens: a camera, a light, a ground and a sphere.
  static SceneDesc default_scene();

  const SceneDesc& scene() const { return scene_; }
  const std::filesystem::path& file() const { return file_; }  // empty until saved
  bool dirty() const { return history_.state_id() != saved_state_; }
  // Changes whenever the scene does (edits, undo, redo, open), for re-rendering.
  uint64_t revision() const { return revision_; }
  // "cornell.json*" style: file name and an unsaved mark.
  std::string display_name() const;

  // `selection` (what was selected before the edit) comes back on undo; see CommandStack.
  // The tracks follow (core/document/animation_edit.h): an animated parameter the edit
  // changed is keyed at the current frame, and tracks of parameters it took away go
  // with them. An edit of the current frame alone is set_frame.
  void edit(SceneDesc after, std::string label, std::string merge_key = {}, Selection selection = {});
  // Shows another frame (render.frame): no undo step, and the document stays saved.
  void set_frame(double frame);
  void end_merge() { history_.end_merge(); }
  bool undo(Selection* selection = nullptr);
  // The newest step taken back with no redo entry (see CommandStack::discard_newest).
  bool discard_newest();
  bool redo(Selection* selection = nullptr);
  const CommandStack& history() const { return history_; }

  // Replaces the document; on failure the current one stays and *errors says why. A
  // document that opens but cannot render yet (a dangling name, an unset file) lists
  // why in *warnings, so the user can mend it. Files it names that are not on disk
  // render as placeholders: with `missing_files` given they are listed there instead,
  // one line per file with who uses it (asset_relink.h), else in *warnings.
  bool open(const std::filesystem::path& file, std::vector<std::string>* errors,
            std::vector<std::string>* warnings = nullptr, std::vector<std::string>* missing_files = nullptr);
  // The same for a file already read (for editing) elsewhere, e.g. by a SceneLoader.
  bool open_loaded(SceneLoadResult loaded, const std::filesystem::path& file,
                   std::vector<std::string>* errors, std::vector<std::string>* warnings = nullptr,
                   std::vector<std::string>* missing_files = nullptr);
  void reset(SceneDesc scene, std::filesystem::path file = {}, bool dirty = false);
  bool save(std::string* error);
  bool save_as(const std::filesystem::path& file, std::string* error);

 private:
  SceneDesc scene_;
  std::filesystem::path file_;
  CommandStack history_;
  uint64_t saved_state_ = 0;
  uint64_t revision_ = 1;
};

}  // namespace inkray
