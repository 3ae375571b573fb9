#include "ui/editor_app.h"

#include "ui/app_paths.h"
#include "ui/camera_controller.h"
#include "ui/log_panel.h"
#include "ui/properties_panel.h"
#include "ui/render_panel.h"
#include "ui/scene_edits.h"
#include "ui/scene_graph_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <thread>

namespace inkray {
namespace {

constexpr float kSideWidth = 300.f;
constexpr float kPropertiesWidth = 380.f;
constexpr float kBottomHeight = 250.f;
// The viewport's share of the height when the node editor is open: at 1600 x 900 the
// example graphs (about 490 units tall) then fit the canvas at zoom 1, where text is sharp.
constexpr float kNodeSplit = 0.4f;
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoBringToFrontOnFocus;

// The UI thread keeps a core for itself, so frames stay smooth while rendering.
int viewport_threads(int requested) {
  if (requested > 0) return requested;
  return std::max(1, int(std::thread::hardware_concurrency()) - 1);
}

bool operator_equal(const ViewportView& a, const ViewportView& b) {
  return a.display == b.display && a.encoding.exposure == b.encoding.exposure &&
         a.encoding.transform == b.encoding.transform && a.highlight_object == b.highlight_object;
}

}  // namespace

EditorApp::EditorApp(EditorOptions options)
    : options_(std::move(options)),
      renderer_(viewport_threads(options_.threads)),
      viewport_(std::make_unique<ViewportPanel>()),
      swatches_(std::make_unique<MaterialSwatches>()),
      recent_(editor_config_dir() / "recent.txt"),
      autosave_(editor_config_dir() / "recovery.json", options_.autosave_interval) {
  recent_.load();
  state_.swatches = swatches_.get();
  state_.home_camera = state_.document.scene().camera;
  if (options_.offer_recovery) {
    std::vector<std::string> errors;
    recovery_ = autosave_.find(&errors);
    for (const auto& e : errors) state_.log.warning("recovery file unreadable: " + e);
  }
  // The file named on the command line is read before the first frame, so scripted
  // runs (--select, --screenshot) see it; files opened later are read in the background.
  if (!options_.scene.empty()) finish_open(options_.scene, load_scene(options_.scene, ReadFor::editing));
  state_.log.info("viewport renders on " + std::to_string(renderer_.threads()) + " threads");
}

EditorApp::~EditorApp() {
  // Reached only on a clean exit: the recovery file is for crashes.
  if (!recovery_) autosave_.clear();
}

std::string EditorApp::window_title() const { return state_.document.display_name() + " - inkray"; }

void EditorApp::request_quit() { guarded(Pending::quit); }

void EditorApp::guarded(Pending action, std::filesystem::path file) {
  pending_ = action;
  pending_file_ = std::move(file);
  if (state_.document.dirty()) {
    ask_unsaved_ = true;
  } else {
    run(action, pending_file_);
  }
}

void EditorApp::run(Pending action, const std::filesystem::path& file) {
  pending_ = Pending::none;
  switch (action) {
    case Pending::new_document:
      state_.document.reset(Document::default_scene());
      state_.selection = {};
      state_.home_camera = state_.document.scene().camera;
      break;
    case Pending::open_dialog:
      dialog_purpose_ = DialogPurpose::open;
      file_dialog_.open("Open scene", FileDialog::Mode::open, {".json"},
                        state_.document.file().empty() ? std::filesystem::current_path() : state_.document.file());
      break;
    case Pending::open_file: open_file(file); break;
    case Pending::quit: quit_ = true; break;
    case Pending::none: break;
  }
}

void EditorApp::open_file(const std::filesystem::path& file) {
  loader_.start(file);
  state_.log.info("opening " + file.string());
}

void EditorApp::finish_open(const std::filesystem::path& file, SceneLoadResult loaded) {
  if (loaded.cancelled) {
    state_.log.info("opening " + file.string() + " cancelled");
    return;
  }
  std::vector<std::string> errors, warnings;
  if (!state_.document.open_loaded(std::move(loaded), file, &errors, &warnings)) {
    // The current document stays; the errors go to a dialog and the log.
    for (const auto& e : errors) state_.log.error(e);
    load_errors_ = std::move(errors);
    show_load_errors_ = true;
    return;
  }
  state_.selection = {};
  state_.home_camera = state_.document.scene().camera;
  state_.region = {};
  recent_.add(file);
  state_.log.info("opened " + file.string());
  for (const auto& w : warnings) state_.log.warning(w + " (the scene opens, but renders once this is mended)");
}

void EditorApp::save(bool choose_file) {
  if (choose_file || state_.document.file().empty()) {
    dialog_purpose_ = DialogPurpose::save_as;
    file_dialog_.open("Save scene as", FileDialog::Mode::save, {".json"},
                      state_.document.file().empty() ? std::filesystem::current_path() / "untitled.json"
                                                     : state_.document.file());
    return;
  }
  std::string error;
  if (state_.document.save(&error)) {
    state_.log.info("saved " + state_.document.file().string());
    autosave_.clear();
    recent_.add(state_.document.file());
  } else {
    state_.log.error(error);
  }
}

void EditorApp::frame_selected() {
  const SceneDesc& scene = state_.document.scene();
  Point3 center(0.f);
  float radius = 1.f;
  if (state_.selection.kind == ItemKind::object && is_valid(scene, state_.selection)) {
    object_bounds(scene.objects[size_t(state_.selection.index)], &center, &radius);
  } else if (auto compiled = renderer_.scene()) {
    center = compiled->scene_center;
    radius = compiled->scene_radius;
  } else {
    return;
  }
  SceneDesc edited = scene;
  edited.camera = frame_sphere(scene.camera, center, radius);
  state_.edit(std::move(edited), "Frame selected");
}

void EditorApp::start_export() {
  const ExportSettings& e = state_.export_settings;
  ExportRequest request;
  request.scene = state_.document.scene();
  std::filesystem::path out = e.output;
  if (out.is_relative() && !state_.document.file().empty()) out = state_.document.file().parent_path() / out;
  request.output = out;
  request.spp = e.spp;
  request.time_seconds = e.time_limit;
  for (size_t i = 0; i < kAovNames.size(); ++i) {
    if (e.aovs[i]) request.aovs.push_back(Aov(i));
  }
  // One thread: the viewport keeps the rest and stays interactive.
  request.threads = 1;
  state_.log.info("exporting " + out.string() + " at " + std::to_string(e.spp) + " spp");
  state_.export_job = std::make_unique<ExportJob>(std::move(request));
}

void EditorApp::menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New", "Ctrl+N")) guarded(Pending::new_document);
    if (ImGui::MenuItem("Open...", "Ctrl+O")) guarded(Pending::open_dialog);
    if (ImGui::BeginMenu("Open recent", !recent_.files().empty())) {
      for (const auto& f : recent_.files()) {
        if (ImGui::MenuItem(f.string().c_str())) guarded(Pending::open_file, f);
      }
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Save", "Ctrl+S")) save(false);
    if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S")) save(true);
    ImGui::Separator();
    if (ImGui::MenuItem("Export render...")) state_.want_export = true;
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) request_quit();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const CommandStack& h = state_.document.history();
    if (ImGui::MenuItem(("Undo " + h.undo_label()).c_str(), "Ctrl+Z", false, h.can_undo())) state_.document.undo();
    if (ImGui::MenuItem(("Redo " + h.redo_label()).c_str(), "Ctrl+Y", false, h.can_redo())) state_.document.redo();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame selected", "F")) state_.want_frame_selected = true;
    ImGui::MenuItem("Node editor", nullptr, &show_node_editor_);
    if (ImGui::MenuItem("Reset camera")) {
      SceneDesc s = state_.document.scene();
      s.camera = state_.home_camera;
      state_.edit(std::move(s), "Reset camera");
    }
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void EditorApp::shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || file_dialog_.is_open()) return;
  // With the node canvas focused, Delete and duplicate act on its nodes, not on the scene.
  const bool nodes_have_keys = show_node_editor_ && node_editor_.focused();
  if (io.KeyCtrl) {
    if (ImGui::IsKeyPressed('N', false)) guarded(Pending::new_document);
    if (ImGui::IsKeyPressed('O', false)) guarded(Pending::open_dialog);
    if (ImGui::IsKeyPressed('S', false)) save(io.KeyShift);
    if (ImGui::IsKeyPressed('Z', false)) io.KeyShift ? state_.document.redo() : state_.document.undo();
    if (ImGui::IsKeyPressed('Y', false)) state_.document.redo();
    if (ImGui::IsKeyPressed('D', false) && !nodes_have_keys) {
      SceneDesc s = state_.document.scene();
      const Selection copy = duplicate_item(s, state_.selection);
      if (copy.kind != ItemKind::none) {
        state_.edit(std::move(s), "Duplicate");
        state_.selection = copy;
      }
    }
  } else if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Delete), false) && !nodes_have_keys) {
    SceneDesc s = state_.document.scene();
    if (delete_item(s, state_.selection)) {
      state_.edit(std::move(s), "Delete");
      state_.selection = {};
    }
  }
}

void EditorApp::layout(float width, float height) {
  const float top = ImGui::GetFrameHeight();  // the menu bar
  const float body = height - top;
  const float centre_w = std::max(width - kSideWidth - kPropertiesWidth, 200.f);
  // With the node editor open, it spans the scene and viewport columns below them, and
  // the output tabs move under the properties: nodes need width more than the log does.
  const bool nodes = show_node_editor_;
  const float viewport_h =
      nodes ? std::max(std::floor(body * kNodeSplit), 150.f) : std::max(body - kBottomHeight, 150.f);
  const float right_x = kSideWidth + centre_w;
  const float properties_h = nodes ? std::max(body - kBottomHeight, 150.f) : body;

  ImGui::SetNextWindowPos(ImVec2(0, top));
  ImGui::SetNextWindowSize(ImVec2(kSideWidth, nodes ? viewport_h : body));
  if (ImGui::Begin("Scene", nullptr, kPanelFlags)) draw_scene_graph_panel(state_);
  ImGui::End();

  ImGui::SetNextWindowPos(ImVec2(kSideWidth, top));
  ImGui::SetNextWindowSize(ImVec2(centre_w, viewport_h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
  if (ImGui::Begin("Viewport", nullptr, kPanelFlags | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
    viewport_frame_ = viewport_->draw(state_, renderer_);
  }
  ImGui::End();
  ImGui::PopStyleVar();

  if (nodes) {
    ImGui::SetNextWindowPos(ImVec2(0, top + viewport_h));
    ImGui::SetNextWindowSize(ImVec2(right_x, body - viewport_h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 3));
    // No title bar: the panel's first row is its title, and the canvas gets the height.
    if (ImGui::Begin("Node editor", nullptr,
                     kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                         ImGuiWindowFlags_NoScrollWithMouse)) {
      node_editor_.draw(state_, &show_node_editor_);
    }
    ImGui::End();
    ImGui::PopStyleVar();
  }

  if (nodes) {
    ImGui::SetNextWindowPos(ImVec2(right_x, top + properties_h));
    ImGui::SetNextWindowSize(ImVec2(kPropertiesWidth, body - properties_h));
  } else {
    ImGui::SetNextWindowPos(ImVec2(kSideWidth, top + viewport_h));
    ImGui::SetNextWindowSize(ImVec2(centre_w, body - viewport_h));
  }
  if (ImGui::Begin("Output", nullptr, kPanelFlags)) {
    if (ImGui::BeginTabBar("bottom_tabs")) {
      if (ImGui::BeginTabItem("Render")) {
        draw_render_panel(state_, renderer_);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Log")) {
        draw_log_panel(state_.log);
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    }
  }
  ImGui::End();

  ImGui::SetNextWindowPos(ImVec2(right_x, top));
  ImGui::SetNextWindowSize(ImVec2(kPropertiesWidth, properties_h));
  if (ImGui::Begin("Properties", nullptr, kPanelFlags)) draw_properties_panel(state_);
  ImGui::End();
}

void EditorApp::dialogs() {
  std::filesystem::path chosen;
  if (file_dialog_.draw(&chosen)) {
    switch (dialog_purpose_) {
      case DialogPurpose::open: open_file(chosen); break;
      case DialogPurpose::save_as: {
        std::string error;
        if (state_.document.save_as(chosen, &error)) {
          state_.log.info("saved " + chosen.string());
          recent_.add(chosen);
          autosave_.clear();
        } else {
          state_.log.error(error);
        }
        break;
      }
      case DialogPurpose::add_mesh: {
        SceneDesc s = state_.document.scene();
        state_.selection = add_mesh(s, chosen.string());
        state_.edit(std::move(s), "Add mesh");
        break;
      }
    }
  }
  if (loader_.busy() && !ImGui::IsPopupOpen("Opening")) ImGui::OpenPopup("Opening");
  if (ImGui::BeginPopupModal("Opening", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("Reading %s ... %.1f s", loader_.file().filename().string().c_str(), loader_.seconds());
    if (ImGui::Button("Cancel")) loader_.cancel();
    if (!loader_.busy()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (ask_unsaved_) {
    ImGui::OpenPopup("Unsaved changes");
    ask_unsaved_ = false;
  }
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s has unsaved changes.", state_.document.display_name().c_str());
    if (ImGui::Button("Save")) {
      save(false);
      ImGui::CloseCurrentPopup();
      if (!state_.document.dirty()) run(pending_, pending_file_);
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      ImGui::CloseCurrentPopup();
      run(pending_, pending_file_);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      pending_ = Pending::none;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  if (show_load_errors_) {
    ImGui::OpenPopup("Could not open the scene");
    show_load_errors_ = false;
  }
  ImGui::SetNextWindowSize(ImVec2(640, 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal("Could not open the scene", nullptr)) {
    ImGui::TextWrapped("The current document is unchanged. Problems found:");
    ImGui::BeginChild("errors", ImVec2(0, 200), true);
    for (const auto& e : load_errors_) ImGui::TextWrapped("%s", e.c_str());
    ImGui::EndChild();
    if (ImGui::Button("OK")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (recovery_) ImGui::OpenPopup("Recover unsaved work?");
  if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The editor did not exit cleanly. Restore the autosaved document%s%s?",
                recovery_ && !recovery_->original.empty() ? " of " : "",
                recovery_ ? recovery_->original.string().c_str() : "");
    if (ImGui::Button("Restore")) {
      state_.document.reset(std::move(recovery_->scene), recovery_->original, true);
      state_.home_camera = state_.document.scene().camera;
      state_.log.info("restored the autosaved document");
      recovery_.reset();
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      recovery_.reset();
      autosave_.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

void EditorApp::sync_renderer() {
  state_.selection = validated(state_.document.scene(), state_.selection);
  state_.view.highlight_object = state_.selection.kind == ItemKind::object ? state_.selection.index : -1;
  if (first_sync_ || !operator_equal(state_.view, sent_view_)) {
    renderer_.set_view(sent_view_ = state_.view);
    view_sent_time_ = std::chrono::steady_clock::now();
  }
  ViewportLimits limits = state_.limits;
  if (limits.spp <= 0) limits.spp = state_.document.scene().render.spp;
  if (limits.time_seconds <= 0.0) limits.time_seconds = state_.document.scene().render.time_limit;
  if (first_sync_ || limits.spp != sent_limits_.spp || limits.time_seconds != sent_limits_.time_seconds ||
      limits.noise_target != sent_limits_.noise_target) {
    renderer_.set_limits(sent_limits_ = limits);
  }
  if (first_sync_ || state_.paused != sent_paused_) renderer_.set_paused(sent_paused_ = state_.paused);
  const RegionRect& r = state_.region;
  if (r.x0 != sent_region_.x0 || r.y0 != sent_region_.y0 || r.x1 != sent_region_.x1 || r.y1 != sent_region_.y1) {
    renderer_.set_region(sent_region_ = r);
  }
  if (state_.document.revision() != submitted_doc_revision_) {
    submitted_doc_revision_ = state_.document.revision();
    submitted_render_revision_ = renderer_.submit(state_.document.scene());
    submit_times_[submitted_render_revision_] = std::chrono::steady_clock::now();
  }
  // Swatches wait while the viewport catches up with an edit: its first pixels come first.
  const auto shown = renderer_.latest();
  const bool viewport_catching_up =
      !shown || shown->revision != submitted_render_revision_ || shown->divisor > 1;
  swatches_->update(state_.document.scene(), viewport_catching_up);
  first_sync_ = false;
}

void EditorApp::poll_background() {
  if (auto loaded = loader_.take()) finish_open(loader_.file(), std::move(*loaded));
  if (std::vector<std::string> problems = renderer_.take_messages(); !problems.empty()) {
    for (const auto& m : problems) state_.log.error(m);
    state_.render_problems = std::move(problems);
  }
  if (viewport_frame_.new_revision_shown != 0) state_.render_problems.clear();
  if (viewport_frame_.new_revision_shown != 0) {
    const auto it = submit_times_.find(viewport_frame_.new_revision_shown);
    if (it != submit_times_.end()) {
      latencies_ms_.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - it->second).count());
      submit_times_.erase(submit_times_.begin(), std::next(it));
      if (auto s = renderer_.latest()) render_latencies_ms_.push_back(s->submit_to_publish_ms);
    }
  }
  if (auto s = renderer_.latest(); s && s->finished && s->revision != logged_finish_revision_) {
    logged_finish_revision_ = s->revision;
    char line[200];
    std::snprintf(line, sizeof line, "viewport done: %u spp in %.2f s, %.2f Mrays/s, estimated error %.2f%%",
                  s->stats.spp, s->stats.elapsed_seconds,
                  s->stats.elapsed_seconds > 0 ? double(s->stats.rays) / s->stats.elapsed_seconds * 1e-6 : 0.0,
                  s->stats.relative_error * 100.0);
    state_.log.info(line);
  }
  if (state_.export_job && state_.export_job->done()) {
    if (const std::string e = state_.export_job->error(); !e.empty()) state_.log.error("export: " + e);
    for (const auto& f : state_.export_job->written()) state_.log.info("wrote " + f.string());
    state_.export_job.reset();
  }
  autosave_.tick(state_.document.scene(), state_.document.file(), state_.document.revision(),
                 state_.document.dirty(), std::chrono::steady_clock::now());
}

void EditorApp::frame(float window_width, float window_height) {
  menu_bar();
  shortcuts();
  layout(window_width, window_height);
  dialogs();
  if (state_.want_frame_selected) frame_selected(), state_.want_frame_selected = false;
  if (state_.want_add_mesh) {
    state_.want_add_mesh = false;
    dialog_purpose_ = DialogPurpose::add_mesh;
    const std::filesystem::path start =
        state_.document.scene().base_dir.empty() ? std::filesystem::current_path() : state_.document.scene().base_dir;
    file_dialog_.open("Add mesh", FileDialog::Mode::open, {".obj"}, start);
  }
  if (state_.want_node_editor) state_.want_node_editor = false, show_node_editor_ = true;
  if (state_.want_export) {
    state_.want_export = false;
    if (!state_.export_job) start_export();
  }
  // A drag is one undo step: merging ends when no widget is held.
  if (!ImGui::IsAnyItemActive()) state_.document.end_merge();
  sync_renderer();
  poll_background();
}

}  // namespace inkray
