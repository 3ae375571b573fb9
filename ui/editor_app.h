// The editor's shell: menu bar, shortcuts, the resizable panel layout, dialogs
// (file, unsaved changes, load errors, crash recovery, help), dropped files, and the
// link between the document and the background renderer. Windowing lives in app/;
// this draws one ImGui frame at a time.
#pragma once

#include "ui/model/autosave.h"
#include "ui/model/editor_state.h"
#include "ui/panels/export_dialog.h"
#include "ui/widgets/file_dialog.h"
#include "ui/panels/help_window.h"
#include "ui/widgets/material_swatches.h"
#include "ui/panels/missing_assets_panel.h"
#include "ui/nodes/node_editor_panel.h"
#include "ui/model/recent_files.h"
#include "ui/model/scene_loader.h"
#include "ui/panels/timeline_panel.h"
#include "ui/model/ui_settings.h"
#include "ui/viewport/viewport_panel.h"

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

namespace inkray {

struct EditorOptions {
  std::filesystem::path scene;  // opened at start when set
  int threads = 0;              // viewport render threads; 0: all but one core for the UI
  bool offer_recovery = true;
  std::chrono::seconds autosave_interval{120};
  // Keys and mouse to play back, for tests (InputScript, editor_app.cpp): the editor's
  // --input-script.
  std::filesystem::path input_script;
};

class InputScript;

class EditorApp {
 public:
  explicit EditorApp(EditorOptions options);
  ~EditorApp();

  // Draws the whole UI for a window of the given size; call between ImGui::NewFrame and ImGui::Render.
  void frame(float window_width, float window_height);
  std::string window_title() const;
  // The window's close button: quits at once, or asks first when there are unsaved changes.
  void request_quit();
  bool should_quit() const { return quit_; }
  // Returns when the renderer has an image the viewport has not shown, or at `until`.
  void wait_for_image(std::chrono::steady_clock::time_point until) const {
    renderer_.wait_for_generation(viewport_->uploaded_generation(), until);
  }

  // Files dropped on the window, handled at the next frame (ui/model/file_drop.h).
  void drop(std::vector<std::filesystem::path> files);
  // The monitor's content scale (GLFW); the UI scale is it times the user's setting.
  void set_content_scale(float scale) { content_scale_ = scale; }
  float ui_scale() const { return content_scale_ * settings_.ui_scale; }
  // The user's interface size (View > Larger/Smaller), saved between runs.
  void set_ui_scale_setting(float scale);

  EditorState& state() { return state_; }
  // View > Node editor: the selected material's nodes below the viewport.
  void show_node_editor(bool show) { show_node_editor_ = show; }
  const NodeEditorPanel& node_editor() const { return node_editor_; }
  ExportUi& export_ui() { return export_ui_; }
  const ViewportPanel& viewport() const { return *viewport_; }
  const ViewportFrame& viewport_frame() const { return viewport_frame_; }
  ProgressiveRenderer& renderer() { return renderer_; }
  // Submit-to-first-pixels-on-screen latencies, one per edit that reached the screen.
  const std::vector<double>& edit_latencies_ms() const { return latencies_ms_; }
  // The renderer's part of it: submit to the snapshot's publication (compile + preview pass + resolve).
  const std::vector<double>& render_latencies_ms() const { return render_latencies_ms_; }
  // For inkray --measure-edits: the renderer revision of the newest submit, and when the
  // view (exposure, display) was last sent.
  uint64_t submitted_revision() const { return submitted_render_revision_; }
  std::chrono::steady_clock::time_point view_sent_time() const { return view_sent_time_; }

 private:
  enum class Pending { none, new_document, open_dialog, open_file, quit };

  void menu_bar();
  void shortcuts();
  void layout(float width, float height);
  // Begins a panel window at its place in the layout; a drag of its inner edges resizes the layout.
  bool begin_panel(const char* name, Panel panel, const PanelRects& placed, int imgui_flags);
  void right_tabs();
  void handle_drops();
  void change_ui_scale(float factor);
  void dialogs();
  void sync_renderer();
  void poll_background();
  // Moves the frame on while playing, by the clock, once the viewport shows the last one.
  void advance_playback();

  void guarded(Pending action, std::filesystem::path file = {});  // asks about unsaved changes first
  void run(Pending action, const std::filesystem::path& file);
  void open_file(const std::filesystem::path& file);  // reads on loader_, finishes in poll_background
  void finish_open(const std::filesystem::path& file, SceneLoadResult loaded);
  void save(bool choose_file);
  void frame_selected();

  EditorOptions options_;
  EditorState state_;
  ExportUi export_ui_;  // after state_: its exports stop before the state they report to goes
  ProgressiveRenderer renderer_;
  std::unique_ptr<ViewportPanel> viewport_;
  ViewportFrame viewport_frame_;
  NodeEditorPanel node_editor_;
  std::unique_ptr<MaterialSwatches> swatches_;
  bool show_node_editor_ = false;
  // The right column's tabs: the selection's properties, the line sets. A tab asked for
  // (View > Line sets, the outlines' "Edit in the Line sets tab") is brought forward once.
  enum class RightTab { none, properties, line_sets } right_tab_request_ = RightTab::none;
  FileDialog file_dialog_;
  HelpWindow help_;
  MissingAssetsPanel missing_assets_;
  UiSettings settings_;
  bool settings_changed_ = false;  // written once the mouse is released, not on every frame of a drag
  float content_scale_ = 1.f;
  std::vector<std::filesystem::path> dropped_;
  std::string drop_problem_, drop_message_;  // why a dropped file could not be used: shown in a dialog
  enum class DialogPurpose { open, save_as, add_mesh } dialog_purpose_ = DialogPurpose::open;
  RecentFiles recent_;
  Autosave autosave_;
  SceneLoader loader_;

  Pending pending_ = Pending::none;
  std::filesystem::path pending_file_;
  bool ask_unsaved_ = false;
  std::vector<std::string> load_errors_;
  bool show_load_errors_ = false;
  std::optional<Recovery> recovery_;
  bool quit_ = false;

  // Playback and the keys that move the frame (over the viewport or the timeline).
  PlaybackClock playback_;
  bool was_playing_ = false;
  double played_frame_ = 0.0;    // the frame playback last set
  RenderSettings played_range_;  // the range and rate it counts in
  bool frames_hovered_ = false;  // the viewport or the timeline, last frame
  std::unique_ptr<InputScript> script_;

  // What the renderer has been told, to send only changes.
  uint64_t submitted_doc_revision_ = 0;
  uint64_t submitted_render_revision_ = 0;
  std::chrono::steady_clock::time_point view_sent_time_;
  ViewportView sent_view_;
  ViewportLimits sent_limits_;
  RegionRect sent_region_;
  bool sent_paused_ = false;
  bool first_sync_ = true;
  uint64_t logged_finish_revision_ = 0;

  std::map<uint64_t, std::chrono::steady_clock::time_point> submit_times_;
  std::vector<double> latencies_ms_, render_latencies_ms_;
};

}  // namespace inkray
