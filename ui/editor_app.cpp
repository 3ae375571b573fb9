#include "ui/editor_app.h"

#include "core/document/animation.h"
#include "ui/model/app_paths.h"
#include "ui/viewport/camera_controller.h"
#include "ui/model/file_drop.h"
#include "ui/panels/line_sets_panel.h"
#include "ui/panels/log_panel.h"
#include "ui/panels/properties_panel.h"
#include "ui/panels/render_panel.h"
#include "ui/model/scene_edits.h"
#include "ui/panels/scene_graph_panel.h"
#include "ui/widgets/widget_report.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>
#include <utility>

namespace inkray {
namespace {

// Panels are resized by dragging their inner edges (begin_panel), never moved.
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus;

std::filesystem::path settings_file() { return editor_config_dir() / "editor.txt"; }

// The UI thread keeps a core for itself, so frames stay smooth while rendering.
int viewport_threads(int requested) {
  if (requested > 0) return requested;
  return std::max(1, int(std::thread::hardware_concurrency()) - 1);
}

}  // namespace

// Scripted input for tests: the keys and mouse GLFW's callbacks would deliver, one
// command a frame (a key or a click takes two: press, release), so a run under Xvfb is
// repeatable. A text file, one command a line ('#' starts a comment):
//   wait N              let N frames pass
//   wait-ms MS          let MS milliseconds pass
//   move X Y            the cursor to window pixels
//   hover NAME [FX FY]  the cursor onto a widget the widget report names (FX FY: where
//                       in it, as fractions; its centre by default)
//   down [B] / up [B]   hold or release a mouse button (left, right, middle)
//   click [B]           press it and release it the next frame
//   key [ctrl+][shift+][alt+]KEY   press a key (a letter, a digit, space, left, right,
//                       up, down, escape, enter, tab, backspace, delete, home, end),
//                       released the next frame
//   type TEXT           characters, as typed into a focused field
//   print-frame         prints "frame F" (the current frame)
//   print-value PATH    prints "value PATH V..." (the parameter at the current frame)
//   print-keys PATH     prints "keys PATH F..." (the frames of its keys)
// The script ends by printing "input script: done"; a command it cannot do prints why
// and ends it.
class InputScript {
 public:
  explicit InputScript(std::vector<std::string> lines) : lines_(std::move(lines)) {}

  // Runs at the end of a frame; what it does reaches ImGui at the next one.
  void step(EditorState& state) {
    if (finished_) return;
    GLFWwindow* window = glfwGetCurrentContext();
    if (!window) return;
    if (!entered_) ImGui_ImplGlfw_CursorEnterCallback(window, 1), entered_ = true;
    // A key or a click is released the frame after its press, and the next command waits
    // one frame more, so a key pressed twice in a row reads as two presses.
    if (!held_keys_.empty() || release_after_click_ >= 0) {
      for (int key : held_keys_) ImGui_ImplGlfw_KeyCallback(window, key, 0, GLFW_RELEASE, 0);
      held_keys_.clear();
      merge_key_mods();
      if (release_after_click_ >= 0) {
        buttons_[release_after_click_] = false;
        ImGui_ImplGlfw_MouseButtonCallback(window, release_after_click_, GLFW_RELEASE, 0);
        release_after_click_ = -1;
      }
      return;
    }
    // A held button is pressed again each frame: ImGui's backend reads a press for one
    // frame, and the real button state from GLFW, which a script cannot set.
    for (int b = 0; b < 3; ++b)
      if (buttons_[b]) ImGui_ImplGlfw_MouseButtonCallback(window, b, GLFW_PRESS, 0);
    if (wait_frames_ > 0) return void(--wait_frames_);
    if (std::chrono::steady_clock::now() < wait_until_) return;
    if (next_ >= lines_.size()) {
      finished_ = true;
      std::printf("input script: done\n");
      std::fflush(stdout);
      state.report_params = false;
      return;
    }
    const std::string line = lines_[next_++];
    std::string why = run(state, window, line);
    if (why == kRetry && ++retries_ < 120) {
      --next_;  // a widget not drawn yet (a panel opening): try again next frame
      return;
    }
    retries_ = 0;
    if (why == kRetry) why = "no widget of that name was drawn";
    if (!why.empty()) {
      std::fprintf(stderr, "input script: line %zu \"%s\": %s\n", next_, line.c_str(), why.c_str());
      finished_ = true;
    }
  }

 private:
  static constexpr const char* kRetry = "retry";

  std::string run(EditorState& state, GLFWwindow* window, const std::string& line) {
    std::istringstream words(line);
    std::string verb;
    words >> verb;
    if (verb.empty() || verb[0] == '#') return {};
    if (verb == "wait") {
      int frames = 0;
      if (!(words >> frames) || frames < 1) return "expected a number of frames";
      wait_frames_ = frames - 1;
    } else if (verb == "wait-ms") {
      int ms = 0;
      if (!(words >> ms) || ms < 0) return "expected milliseconds";
      wait_until_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
    } else if (verb == "move") {
      double x = 0, y = 0;
      if (!(words >> x >> y)) return "expected x and y";
      glfwSetCursorPos(window, x, y);
    } else if (verb == "hover") {
      std::string name;
      double fx = 0.5, fy = 0.5;
      if (!(words >> name)) return "expected a widget name";
      words >> fx >> fy;
      double rect[4];
      if (!find_widget(name, rect)) return kRetry;
      glfwSetCursorPos(window, rect[0] + fx * (rect[2] - rect[0]), rect[1] + fy * (rect[3] - rect[1]));
    } else if (verb == "down" || verb == "up" || verb == "click") {
      std::string name = "left";
      words >> name;
      const int b = name == "left" ? 0 : name == "right" ? 1 : name == "middle" ? 2 : -1;
      if (b < 0) return "unknown mouse button " + name;
      buttons_[b] = verb != "up";
      ImGui_ImplGlfw_MouseButtonCallback(window, b, buttons_[b] ? GLFW_PRESS : GLFW_RELEASE, 0);
      if (verb == "click") release_after_click_ = b;
    } else if (verb == "key") {
      std::string combo;
      if (!(words >> combo)) return "expected a key";
      std::vector<int> keys;
      for (size_t start = 0; start <= combo.size();) {
        const size_t plus = std::min(combo.find('+', start), combo.size());
        const int key = key_code(combo.substr(start, plus - start));
        if (key < 0) return "unknown key " + combo.substr(start, plus - start);
        keys.push_back(key);
        start = plus + 1;
      }
      for (int key : keys) ImGui_ImplGlfw_KeyCallback(window, key, 0, GLFW_PRESS, 0);
      held_keys_ = keys;
      merge_key_mods();
    } else if (verb == "type") {
      std::string text;
      std::getline(words >> std::ws, text);
      for (unsigned char c : text) ImGui_ImplGlfw_CharCallback(window, c);
    } else if (verb == "print-frame") {
      std::printf("frame %g\n", double(state.document.scene().render.frame));
    } else if (verb == "print-value") {
      std::string path;
      std::vector<double> value;
      if (!(words >> path) || !read_target(state.shown(), path, &value)) return "no parameter " + path;
      std::printf("value %s", path.c_str());
      for (double v : value) std::printf(" %.6g", v);
      std::printf("\n");
    } else if (verb == "print-keys") {
      std::string path;
      if (!(words >> path)) return "expected a parameter path";
      std::printf("keys %s", path.c_str());
      if (const TrackDesc* track = find_track(state.document.scene(), path))
        for (const KeyDesc& key : track->keys) std::printf(" %g", key.frame);
      std::printf("\n");
    } else {
      return "unknown command";
    }
    std::fflush(stdout);
    return {};
  }

  // The backend's callbacks run between frames; run inside one, they change io.KeyCtrl
  // and the others after NewFrame merged them into io.KeyMods, which EndFrame checks.
  static void merge_key_mods() {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMods = (io.KeyCtrl ? ImGuiKeyModFlags_Ctrl : 0) | (io.KeyShift ? ImGuiKeyModFlags_Shift : 0) |
                 (io.KeyAlt ? ImGuiKeyModFlags_Alt : 0) | (io.KeySuper ? ImGuiKeyModFlags_Super : 0);
  }

  // GLFW key codes; ImGui 1.86 indexes its key array by them.
  static int key_code(const std::string& name) {
    static const std::pair<const char*, int> kNamed[] = {{"ctrl", GLFW_KEY_LEFT_CONTROL},
                                                         {"shift", GLFW_KEY_LEFT_SHIFT},
                                                         {"alt", GLFW_KEY_LEFT_ALT},
                                                         {"space", GLFW_KEY_SPACE},
                                                         {"left", GLFW_KEY_LEFT},
                                                         {"right", GLFW_KEY_RIGHT},
                                                         {"up", GLFW_KEY_UP},
                                                         {"down", GLFW_KEY_DOWN},
                                                         {"escape", GLFW_KEY_ESCAPE},
                                                         {"enter", GLFW_KEY_ENTER},
                                                         {"tab", GLFW_KEY_TAB},
                                                         {"backspace", GLFW_KEY_BACKSPACE},
                                                         {"delete", GLFW_KEY_DELETE},
                                                         {"home", GLFW_KEY_HOME},
                                                         {"end", GLFW_KEY_END}};
    for (const auto& [n, code] : kNamed)
      if (name == n) return code;
    if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0])))
      return std::toupper(static_cast<unsigned char>(name[0]));
    return -1;
  }

  // The rectangle the widget report gave `name` this frame.
  static bool find_widget(const std::string& name, double rect[4]) {
    std::istringstream report(widget_report::text());
    std::string line;
    while (std::getline(report, line)) {
      std::istringstream words(line);
      std::string n;
      if (words >> n && n == name && words >> rect[0] >> rect[1] >> rect[2] >> rect[3]) return true;
    }
    return false;
  }

  std::vector<std::string> lines_;
  size_t next_ = 0;
  int wait_frames_ = 0;
  std::chrono::steady_clock::time_point wait_until_;
  int retries_ = 0;
  std::vector<int> held_keys_;
  bool buttons_[3] = {false, false, false};
  int release_after_click_ = -1;
  bool entered_ = false;
  bool finished_ = false;
};

EditorApp::EditorApp(EditorOptions options)
    : options_(std::move(options)),
      renderer_(viewport_threads(options_.threads)),
      viewport_(std::make_unique<ViewportPanel>()),
      swatches_(std::make_unique<MaterialSwatches>()),
      recent_(editor_config_dir() / "recent.txt"),
      autosave_(editor_config_dir() / "recovery.json", options_.autosave_interval) {
  recent_.load();
  std::vector<std::string> problems;
  settings_ = read_ui_settings(settings_file(), &problems);
  for (const auto& p : problems) state_.log.warning(p + " (skipped)");
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
  if (!options_.input_script.empty()) {
    std::ifstream in(options_.input_script);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    if (!in.eof()) {
      // A test that cannot play its script must not pass on an editor that did nothing.
      std::fprintf(stderr, "inkray: --input-script: cannot read %s\n",
                   options_.input_script.string().c_str());
      std::exit(2);
    } else {
      script_ = std::make_unique<InputScript>(std::move(lines));
      state_.report_params = true;
    }
  }
}

EditorApp::~EditorApp() {
  // Reached only on a clean exit: the recovery file is for crashes.
  if (!recovery_) autosave_.clear();
  std::string error;
  if (settings_changed_ && !write_ui_settings(settings_file(), settings_, &error)) {
    std::fprintf(stderr, "inkray: %s\n", error.c_str());
  }
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
      file_dialog_.open(
          "Open scene", FileDialog::Mode::open, {".json"},
          state_.document.file().empty() ? std::filesystem::current_path() : state_.document.file());
      break;
    case Pending::open_file:
      open_file(file);
      break;
    case Pending::quit:
      quit_ = true;
      break;
    case Pending::none:
      break;
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
  std::vector<std::string> errors, warnings, missing;
  if (!state_.document.open_loaded(std::move(loaded), file, &errors, &warnings, &missing)) {
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
  for (const auto& w : warnings)
    state_.log.warning(w + " (the scene opens, but renders once this is mended)");
  for (const auto& m : missing) state_.log.warning(m + ": drawn as a placeholder until located");
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
  const SceneDesc& scene = state_.shown();
  Point3 center(0.f);
  float radius = 1.f;
  if (state_.selection.kind == ItemKind::object && is_valid(scene, state_.selection)) {
    object_bounds(scene.objects[size_t(state_.selection.index)], &center, &radius);
  } else if (auto compiled = renderer_.scene()) {
    center = compiled->world->scene_center;
    radius = compiled->world->scene_radius;
  } else {
    return;
  }
  SceneDesc edited = state_.document.scene();
  edited.camera = frame_sphere(scene.camera, center, radius);
  state_.edit(std::move(edited), "Frame selected");
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
    if (ImGui::MenuItem(("Undo " + h.undo_label()).c_str(), "Ctrl+Z", false, h.can_undo()))
      state_.document.undo(&state_.selection);
    if (ImGui::MenuItem(("Redo " + h.redo_label()).c_str(), "Ctrl+Y", false, h.can_redo()))
      state_.document.redo(&state_.selection);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame selected", "F")) state_.want_frame_selected = true;
    ImGui::MenuItem("Node editor", nullptr, &show_node_editor_);
    if (ImGui::MenuItem("Properties")) right_tab_request_ = RightTab::properties;
    if (ImGui::MenuItem("Line sets")) right_tab_request_ = RightTab::line_sets;
    if (ImGui::MenuItem("Reset camera")) {
      SceneDesc s = state_.document.scene();
      s.camera = state_.home_camera;
      state_.edit(std::move(s), "Reset camera");
    }
    ImGui::Separator();
    ImGui::TextDisabled("Interface size %d%%", int(std::round(settings_.ui_scale * 100.f)));
    if (ImGui::MenuItem("Larger", "Ctrl+=")) change_ui_scale(1.1f);
    if (ImGui::MenuItem("Smaller", "Ctrl+-")) change_ui_scale(1.f / 1.1f);
    if (ImGui::MenuItem("Default size", "Ctrl+0")) change_ui_scale(0.f);
    if (ImGui::MenuItem("Reset panel sizes")) settings_.layout = {}, settings_changed_ = true;
    ImGui::EndMenu();
  }
  if (missing_assets_.has_missing()) {
    // A badge in the menu bar, in the placeholders' magenta: files to locate.
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.35f, 1.f, 1.f));
    if (ImGui::MenuItem(missing_assets_.badge_text().c_str())) missing_assets_.show();
    ImGui::PopStyleColor();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Shortcuts and help", "F1")) help_.show_shortcuts();
    if (ImGui::MenuItem("About inkray")) help_.show_about();
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void EditorApp::shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || file_dialog_.is_open()) return;
  // With the node canvas focused, Delete and duplicate act on its nodes, not on the scene.
  const bool nodes_have_keys = show_node_editor_ && node_editor_.focused();
  constexpr int kGlfwKeyF1 = 290;  // ImGui 1.86 names no function keys; its key array is GLFW's
  if (ImGui::IsKeyPressed(kGlfwKeyF1, false)) help_.show_shortcuts();
  if (io.KeyCtrl) {
    // GLFW key codes: '=' 61, '-' 45, '0' 48; the keypad's + and - are 334 and 333.
    if (ImGui::IsKeyPressed('=', false) || ImGui::IsKeyPressed(334, false)) change_ui_scale(1.1f);
    if (ImGui::IsKeyPressed('-', false) || ImGui::IsKeyPressed(333, false)) change_ui_scale(1.f / 1.1f);
    if (ImGui::IsKeyPressed('0', false)) change_ui_scale(0.f);
    if (ImGui::IsKeyPressed('N', false)) guarded(Pending::new_document);
    if (ImGui::IsKeyPressed('O', false)) guarded(Pending::open_dialog);
    if (ImGui::IsKeyPressed('S', false)) save(io.KeyShift);
    if (ImGui::IsKeyPressed('Z', false))
      io.KeyShift ? state_.document.redo(&state_.selection) : state_.document.undo(&state_.selection);
    if (ImGui::IsKeyPressed('Y', false)) state_.document.redo(&state_.selection);
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
    if (delete_item(s, state_.selection) && state_.edit_checked(std::move(s), "Delete"))
      state_.selection = {};
  }
  // The frame, as in Blender: Space plays anywhere; the arrows step over the viewport and
  // the timeline (Shift: to the shot's ends; up and down: to the next and previous key).
  if (io.KeyCtrl || io.KeyAlt) return;
  const auto pressed = [](ImGuiKey key, bool repeat) {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), repeat);
  };
  if (!io.KeyShift && pressed(ImGuiKey_Space, false)) toggle_playback(state_);
  if (!frames_hovered_) return;
  if (pressed(ImGuiKey_LeftArrow, true)) io.KeyShift ? jump_to_end(state_, false) : step_frame(state_, -1);
  if (pressed(ImGuiKey_RightArrow, true)) io.KeyShift ? jump_to_end(state_, true) : step_frame(state_, 1);
  if (pressed(ImGuiKey_UpArrow, false)) jump_to_key(state_, 1);
  if (pressed(ImGuiKey_DownArrow, false)) jump_to_key(state_, -1);
}

bool EditorApp::begin_panel(const char* name, Panel panel, const PanelRects& placed, int imgui_flags) {
  const PanelRect& r = placed[panel];
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  const bool open = ImGui::Begin(name, nullptr, imgui_flags);
  // ImGui resizes the window inside Begin when one of its edges is dragged: fold that
  // into the layout, which places every panel from the next frame on.
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  const PanelRect now{pos.x, pos.y, size.x, size.y};
  if (now.x != r.x || now.y != r.y || now.w != r.w || now.h != r.h) {
    settings_.layout = resized(settings_.layout, panel, placed, now, ui_scale(), show_node_editor_);
    settings_changed_ = true;
  }
  return open;
}

void EditorApp::layout(float width, float height) {
  const float top = ImGui::GetFrameHeight();  // the menu bar
  const PanelRects placed = place_panels(settings_.layout, width, height, top, ui_scale(), show_node_editor_);

  if (begin_panel("Scene", Panel::scene, placed, kPanelFlags)) draw_scene_graph_panel(state_);
  ImGui::End();

  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
  if (begin_panel("Viewport", Panel::viewport, placed,
                  kPanelFlags | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
    viewport_frame_ = viewport_->draw(state_, renderer_);
  }
  frames_hovered_ = ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows);
  ImGui::End();
  ImGui::PopStyleVar();

  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 3));
  // No title bar and a fixed height: its first row is the transport.
  if (begin_panel("Timeline", Panel::timeline, placed,
                  kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
    draw_timeline_panel(state_);
  }
  frames_hovered_ = frames_hovered_ || ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows);
  ImGui::End();
  ImGui::PopStyleVar();

  if (show_node_editor_) {
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 3));
    // No title bar: the panel's first row is its title, and the canvas gets the height.
    if (begin_panel("Node editor", Panel::node_editor, placed,
                    kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                        ImGuiWindowFlags_NoScrollWithMouse)) {
      node_editor_.draw(state_, &show_node_editor_);
    }
    ImGui::End();
    ImGui::PopStyleVar();
  }

  if (begin_panel("Output", Panel::output, placed, kPanelFlags)) {
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

  if (begin_panel("Properties", Panel::properties, placed, kPanelFlags)) right_tabs();
  ImGui::End();
}

void EditorApp::right_tabs() {
  if (!ImGui::BeginTabBar("right_tabs")) return;
  const auto flags = [&](RightTab tab) {
    return right_tab_request_ == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
  };
  const bool properties = ImGui::BeginTabItem("Selection", nullptr, flags(RightTab::properties));
  widget_report::item("tabs.selection");
  if (properties) {
    draw_properties_panel(state_);
    ImGui::EndTabItem();
  }
  const bool line_sets = ImGui::BeginTabItem("Line sets", nullptr, flags(RightTab::line_sets));
  widget_report::item("tabs.line_sets");
  if (line_sets) {
    draw_line_sets_panel(state_);
    ImGui::EndTabItem();
  }
  right_tab_request_ = RightTab::none;
  ImGui::EndTabBar();
}

void EditorApp::set_ui_scale_setting(float scale) {
  settings_.ui_scale = std::clamp(scale, kMinUiScale, kMaxUiScale);
}

void EditorApp::change_ui_scale(float factor) {
  settings_.ui_scale =
      factor == 0.f ? 1.f : std::clamp(settings_.ui_scale * factor, kMinUiScale, kMaxUiScale);
  settings_changed_ = true;
}

void EditorApp::drop(std::vector<std::filesystem::path> files) {
  for (auto& f : files) dropped_.push_back(std::move(f));
}

void EditorApp::handle_drops() {
  std::vector<std::filesystem::path> files;
  files.swap(dropped_);
  for (const auto& file : files) {
    switch (drop_kind(file)) {
      case DropKind::scene:
        guarded(Pending::open_file, file);
        break;
      case DropKind::mesh: {
        SceneDesc s = state_.document.scene();
        const Selection added = add_mesh(s, file.string());
        std::string why;
        if (state_.edit_checked(std::move(s), "Import " + file.filename().string(), &why)) {
          state_.selection = added;
          state_.log.info("imported " + file.string());
        } else {
          drop_problem_ = file.string() + ":\n" + why;
        }
        break;
      }
      case DropKind::image: {
        SceneDesc s = state_.document.scene();
        std::string why;
        if (drop_image_on(s, state_.selection, file, &why)) {
          if (!state_.edit_checked(std::move(s), "Drop " + file.filename().string(), &why)) {
            drop_problem_ = file.string() + ":\n" + why;
            break;
          }
          state_.log.info("set " + file.string() + " on " +
                          item_name(state_.document.scene(), state_.selection));
        } else {
          state_.log.error(why);
          drop_problem_ = why;
        }
        break;
      }
      case DropKind::unknown:
        drop_problem_ =
            file.string() + ": not a scene (.json), a mesh (.obj) or an image (.png, .jpg, .hdr, .tga, .bmp)";
        state_.log.error(drop_problem_);
        break;
    }
  }
}

void EditorApp::dialogs() {
  std::filesystem::path chosen;
  if (file_dialog_.draw(&chosen)) {
    switch (dialog_purpose_) {
      case DialogPurpose::open:
        open_file(chosen);
        break;
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
        state_.selection = add_mesh(s, chosen.string(), state_.add_mesh_native_size);
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
  ImGui::SetNextWindowSize(ImVec2(42 * ImGui::GetFontSize(), 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal("Could not open the scene", nullptr)) {
    ImGui::TextWrapped("The current document is unchanged. Problems found:");
    ImGui::BeginChild("errors", ImVec2(0, 13 * ImGui::GetFontSize()), true);
    for (const auto& e : load_errors_) ImGui::TextWrapped("%s", e.c_str());
    ImGui::EndChild();
    if (ImGui::Button("OK")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (!drop_problem_.empty()) {
    ImGui::OpenPopup("Cannot use the dropped file");
    drop_message_ = std::move(drop_problem_);
    drop_problem_.clear();
  }
  ImGui::SetNextWindowSize(ImVec2(32 * ImGui::GetFontSize(), 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal("Cannot use the dropped file", nullptr)) {
    ImGui::TextWrapped("%s", drop_message_.c_str());
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
  if (first_sync_ || !(state_.view == sent_view_)) {
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
  // An export on all cores pauses the viewport unless the user asked it to keep one.
  const bool paused = state_.paused || export_ui_.wants_viewport_paused();
  if (first_sync_ || paused != sent_paused_) renderer_.set_paused(sent_paused_ = paused);
  const RegionRect& r = state_.region;
  if (r.x0 != sent_region_.x0 || r.y0 != sent_region_.y0 || r.x1 != sent_region_.x1 ||
      r.y1 != sent_region_.y1) {
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
  for (const auto& w : renderer_.take_warnings()) state_.log.warning(w);
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
    std::snprintf(
        line, sizeof line, "viewport done: %u spp in %.2f s, %.2f Mrays/s, estimated error %.2f%%",
        s->stats.spp, s->stats.elapsed_seconds,
        s->stats.elapsed_seconds > 0 ? double(s->stats.rays) / s->stats.elapsed_seconds * 1e-6 : 0.0,
        s->stats.relative_error * 100.0);
    if (s->denoised)
      std::snprintf(line + std::strlen(line), sizeof line - std::strlen(line), " raw, %.2f%% denoised",
                    s->denoised_error * 100.0);
    state_.log.info(line);
  }
  autosave_.tick(state_.document.scene(), state_.document.file(), state_.document.revision(),
                 state_.document.dirty(), std::chrono::steady_clock::now());
}

void EditorApp::frame(float window_width, float window_height) {
  menu_bar();
  shortcuts();
  handle_drops();
  layout(window_width, window_height);
  dialogs();
  help_.draw();
  missing_assets_.draw(state_);
  // Panel sizes are written once a drag ends, not on each of its frames.
  if (settings_changed_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    std::string error;
    if (!write_ui_settings(settings_file(), settings_, &error)) state_.log.error(error);
    settings_changed_ = false;
  }
  if (state_.want_frame_selected) frame_selected(), state_.want_frame_selected = false;
  if (state_.want_add_mesh) {
    state_.want_add_mesh = false;
    dialog_purpose_ = DialogPurpose::add_mesh;
    const std::filesystem::path start = state_.document.scene().base_dir.empty()
                                            ? std::filesystem::current_path()
                                            : state_.document.scene().base_dir;
    file_dialog_.open("Add mesh", FileDialog::Mode::open, {".obj"}, start);
  }
  if (state_.want_node_editor) state_.want_node_editor = false, show_node_editor_ = true;
  if (state_.want_line_sets) state_.want_line_sets = false, right_tab_request_ = RightTab::line_sets;
  if (state_.want_export) state_.want_export = false, export_ui_.open_dialog(state_);
  export_ui_.draw(state_);
  // A drag is one undo step: merging ends when no widget is held.
  if (!ImGui::IsAnyItemActive()) state_.document.end_merge();
  advance_playback();
  sync_renderer();
  poll_background();
  if (script_) {
    widget_report::enable(true);  // the script finds widgets by their reports
    script_->step(state_);
  }
}

void EditorApp::advance_playback() {
  const auto now = PlaybackClock::Clock::now();
  const RenderSettings& r = state_.document.scene().render;
  if (!state_.playing) {
    was_playing_ = false;
    return;
  }
  // Started, or the frame, range or rate changed by hand: count on from where it is.
  const bool range_changed = r.frame_start != played_range_.frame_start ||
                             r.frame_end != played_range_.frame_end || r.fps != played_range_.fps;
  if (!was_playing_ || state_.scrubbing || double(r.frame) != played_frame_ || range_changed) {
    playback_.start(r.frame, now);
    played_frame_ = r.frame;
    played_range_ = r;
    was_playing_ = true;
    if (state_.scrubbing) return;
  }
  // The next frame goes out once the viewport shows this one (or cannot show it): a
  // frame slower than 1/fps is dropped, and playback never queues up behind the renderer.
  const bool shown = viewport_->shown_revision() >= submitted_render_revision_ ||
                     !state_.render_problems.empty() || sent_paused_;
  if (!shown) return;
  const double frame = playback_.frame_at(now, r);
  if (frame == double(r.frame)) return;
  state_.document.set_frame(frame);
  played_frame_ = state_.document.scene().render.frame;
}

}  // namespace inkray
