// Final renders in the editor: the export dialog (output file and format, AOVs,
// limits, resolution, whether the viewport keeps rendering), the progress window over
// the export queue, and the image view each finished export opens. The app shell owns
// one ExportUi, routes File > Export render... to open_dialog(), draws it every frame
// and pauses its viewport while wants_viewport_paused().
#pragma once

#include "ui/model/editor_state.h"
#include "ui/model/export_queue.h"
#include "ui/widgets/file_dialog.h"
#include "ui/widgets/image_view.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace inkray {

class ExportUi {
 public:
  // Fills the dialog for the document: the path from the scene's file (unless the user
  // chose one for this scene already), the resolution from its render settings.
  void open_dialog(const EditorState& state);
  // The dialog, the progress window and the image view; polls the queue, logs what
  // finished and opens its image.
  void draw(EditorState& state);
  bool wants_viewport_paused() const { return queue_.viewport_paused(); }
  const ExportQueue& queue() const { return queue_; }

  // `inkray --export PATH`: the dialog filled in with PATH and Start pressed, as a user
  // would, replacing files that exist. Returns the export's id in queue(), whose entry
  // tells when it finished and what it wrote; 0 when the dialog refused, with the reason
  // in dialog_error().
  uint64_t start_for_test(EditorState& state, const std::filesystem::path& output);
  const std::string& dialog_error() const { return check_.error; }

 private:
  void draw_dialog(EditorState& state);
  void output_row();
  void limits_rows();
  void resolution_row();
  void draw_progress();
  void draw_overwrite_popup(EditorState& state);
  uint64_t start(EditorState& state);

  ExportForm form_;
  ExportFormCheck check_;
  std::filesystem::path form_scene_;  // the scene file form_.output was chosen for
  int scene_width_ = 0, scene_height_ = 0;
  bool keep_aspect_ = true;
  bool dialog_open_ = false, focus_dialog_ = false, ask_overwrite_ = false, progress_open_ = false;
  FileDialog file_dialog_;
  ExportQueue queue_;
  ImageView image_view_;
};

}  // namespace inkray
