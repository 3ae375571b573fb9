// The files the open scene names that are not on disk: a window listing each with
// who uses it and a "Locate..." button, whose choice relinks it and the missing
// files beside it (core/document/asset_relink.h) as one undoable edit. Meanwhile the
// viewport draws them as placeholders.
#pragma once

#include "core/document/asset_relink.h"
#include "ui/model/editor_state.h"
#include "ui/widgets/file_dialog.h"

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

class MissingAssetsPanel {
 public:
  // Checks the disk when due, then draws the window while files are missing (it
  // opens again when the list changes) and the file dialog while one is open.
  void draw(EditorState& state);
  bool has_missing() const { return !missing_.empty(); }
  // "2 files missing - Locate..." for a viewport badge; empty when none is.
  std::string badge_text() const;
  // Opens the window (a click on the badge).
  void show() { open_ = true; }

 private:
  // A scene of many objects costs a stat per file: the disk is checked once a
  // second (a file may appear there), and at once after an open or a relink.
  void refresh(const EditorState& state);
  void relink_to(EditorState& state, const std::filesystem::path& chosen);

  std::vector<MissingAsset> missing_;
  std::filesystem::path document_file_;
  std::chrono::steady_clock::time_point checked_at_;
  bool stale_ = true;
  bool open_ = false;
  FileDialog dialog_;
  std::string locating_;  // the path, as written, the dialog looks for
};

}  // namespace inkray
