// inkray: the editor. GLFW window, OpenGL 3.3 core, Dear ImGui; everything
// else is EditorApp (ui/), and what tests and measurements add is ScriptedRun
// (app/scripted_run.h). Headless runs for tests and measurements:
//   inkray --screenshot OUT.png --frames N [--window-size W H] [--widget-report OUT.txt]
//          [--node-editor MATERIAL --node-layout OUT.txt] [--drop FILE] [SCENE.json]
//   inkray --measure-edits N [--edit KIND,...] [SCENE.json]   (edit latency, frame
//   times and samples kept, per kind of edit)
#include "app/cli_numbers.h"
#include "app/cli_options.h"
#include "app/edit_measurement.h"
#include "app/scripted_run.h"
#include "ui/editor_app.h"
#include "ui/widgets/fonts.h"

#include <GLFW/glfw3.h>
#include <GL/gl.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace {

struct Options {
  bool help = false;
  std::string scene;
  int threads = 0;
  int width = 1600, height = 900;
  std::string input_script;  // keys and mouse moves to play, one a line (ui/editor_app.h)
  float ui_scale = 0.f;      // overrides the saved interface size when set
  inkray::ScriptOptions script;
};

// GLFW's drop callback has no user pointer of its own: the window's points at the app.
void on_drop(GLFWwindow* window, int count, const char** paths) {
  auto* app = static_cast<inkray::EditorApp*>(glfwGetWindowUserPointer(window));
  if (!app) return;
  std::vector<std::filesystem::path> files(paths, paths + count);
  app->drop(std::move(files));
}

void usage() {
  std::puts(
      "usage: inkray [SCENE.json] [options]\n"
      "  --screenshot FILE    after --frames frames (and the first full-resolution image),\n"
      "                       write the window to FILE (PNG) and exit\n"
      "  --frames N           frames to run before the screenshot or exit\n"
      "  --measure-edits N    make N edits of each --edit kind, one every 15 frames, and print per\n"
      "                       kind: edit to first pixels p50/p95, UI frame work p95, and the samples\n"
      "                       kept (spp of the first image showing an edit / spp shown before it)\n"
      "  --edit KIND[,KIND]   kinds to measure (repeatable; default camera): camera (orbit step),\n"
      "                       material (colour of the first object's material), light (intensity of\n"
      "                       the first light, else an emissive strength), transform (move the first\n"
      "                       object), line-colour (outlines.silhouette.color), stroke-parameter\n"
      "                       (hue_jitter of the first stroke emitter), exposure (the viewport's),\n"
      "                       node (a value on a graph node), gizmo-drag (drag the first object's\n"
      "                       move gizmo along an axis, a step every frame)\n"
      "  --threads N          viewport render threads (default: all cores but one)\n"
      "  --window-size W H    window size in pixels (default 1600 900; also --size WxH)\n"
      "  --ui-scale S         interface size (1 = default; the saved setting otherwise)\n"
      "  --widget-report FILE with --screenshot: write the toolbar widgets' rectangles and the\n"
      "                       visible area of their panels (window pixels) to FILE\n"
      "  --drop FILE          after the first frame, drop FILE on the window as GLFW would\n"
      "                       (repeatable)\n"
      "  --scene-dump FILE    with --screenshot: write the document as it then is (JSON) to FILE\n"
      "  --input-script FILE  play the keys, clicks and mouse moves FILE lists, one a line, as the\n"
      "                       frames go by (tests drive the editor with it; ui/editor_app.h)\n"
      "  --export FILE        fill the export dialog with FILE and press Start (replacing files);\n"
      "                       with --screenshot, the screenshot follows the finished export\n"
      "  --select NAME        select the object NAME at start (for screenshots and tests)\n"
      "  --node-editor NAME   select the material NAME and open the node editor on it\n"
      "  --node-layout FILE   with --screenshot: write the node editor's node boxes and link ends\n"
      "                       (screen pixels) to FILE");
}

// The editor's options; what they mean is usage()'s.
const std::vector<inkray::cli::Option<Options>>& editor_options() {
  using inkray::cli::number_option, inkray::cli::text_option, inkray::cli::Range, inkray::cli::Words;
  static const std::vector<inkray::cli::Option<Options>> table = {
      inkray::cli::flag_option({"-h", "--help"}, &Options::help, true),
      text_option<Options>({"--screenshot"}, [](Options& o) -> std::string& { return o.script.screenshot; }),
      number_option<Options>(
          {"--frames"}, [](Options& o) -> int& { return o.script.frames; }, Range<int>{0, 1000000}),
      number_option<Options>(
          {"--measure-edits"}, [](Options& o) -> int& { return o.script.measure_edits; },
          Range<int>{1, 100000}),
      {{"--edit"},
       1,
       [](Options& o, Words w) {
         const std::string list(w[0]);
         for (size_t begin = 0; begin <= list.size();) {
           const size_t end = std::min(list.find(',', begin), list.size());
           const std::string name = list.substr(begin, end - begin);
           const auto& kinds = inkray::measure::kEditKindNames;
           const auto found = std::find(kinds.begin(), kinds.end(), name);
           if (found == kinds.end())
             return "--edit: unknown kind \"" + name +
                    "\" (valid kinds: " + inkray::measure::edit_kind_list() + ")";
           o.script.edit_kinds.push_back(inkray::measure::EditKind(found - kinds.begin()));
           begin = end + 1;
         }
         return std::string();
       }},
      number_option({"--threads"}, &Options::threads, Range<int>{1, 1024}),
      text_option<Options>({"--select"}, [](Options& o) -> std::string& { return o.script.select; }),
      text_option<Options>({"--node-editor"},
                           [](Options& o) -> std::string& { return o.script.node_material; }),
      text_option<Options>({"--node-layout"},
                           [](Options& o) -> std::string& { return o.script.node_layout; }),
      {{"--size"},
       1,
       [](Options& o, Words w) {
         const std::string text(w[0]);
         return std::sscanf(text.c_str(), "%dx%d", &o.width, &o.height) == 2
                    ? std::string()
                    : "--size: expected WIDTHxHEIGHT, got \"" + text + "\"";
       }},
      {{"--window-size"},
       2,
       [](Options& o, Words w) {
         std::string problem = inkray::cli::read_option_number("--window-size", w[0], 64, 16384, &o.width);
         if (problem.empty())
           problem = inkray::cli::read_option_number("--window-size", w[1], 64, 16384, &o.height);
         return problem;
       }},
      number_option({"--ui-scale"}, &Options::ui_scale, Range<float>{0.5f, 3.f}),
      text_option<Options>({"--widget-report"},
                           [](Options& o) -> std::string& { return o.script.widget_report; }),
      text_option<Options>({"--export"}, [](Options& o) -> std::string& { return o.script.export_path; }),
      text_option<Options>({"--scene-dump"}, [](Options& o) -> std::string& { return o.script.scene_dump; }),
      text_option({"--input-script"}, &Options::input_script),
      {{"--drop"},
       1,
       [](Options& o, Words w) {
         o.script.drops.emplace_back(w[0]);
         return std::string();
       }},
  };
  return table;
}

// Reads the command line; false after printing what was wrong.
bool parse(int argc, char** argv, Options* o) {
  const std::string problem = inkray::cli::parse_options<Options>(
      editor_options(), argc, argv, *o, [](Options& opts, std::string_view arg) {
        if (!opts.scene.empty())
          return "unexpected argument \"" + std::string(arg) + "\": only one scene is opened";
        opts.scene = std::string(arg);
        return std::string();
      });
  if (problem.empty()) return true;
  std::fprintf(stderr, "inkray: %s\n", problem.c_str());
  return false;
}

// The monitor's scale: GLFW's content scale where the desktop sets one (Xft.dpi, Wayland,
// macOS), else the monitor's pixel density against the 96 dpi the sizes were drawn for,
// in quarter steps; X servers without a desktop setting report a content scale of 1 on
// 4K monitors too.
float monitor_scale(GLFWwindow* window) {
  float x = 1.f, y = 1.f;
  glfwGetWindowContentScale(window, &x, &y);
  const float content = std::max(x, y);
  if (content != 1.f) return content;
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  int width_mm = 0, height_mm = 0;
  if (monitor) glfwGetMonitorPhysicalSize(monitor, &width_mm, &height_mm);
  if (!mode || width_mm < 100) return 1.f;  // unknown or implausible (projectors report 0)
  const float dpi = float(mode->width) / (float(width_mm) / 25.4f);
  return std::clamp(std::round(dpi / 96.f * 4.f) / 4.f, 1.f, 3.f);
}

// Rebuilds the font atlas when the interface scale changed; the backend uploads it at
// its first frame, and again here on later changes.
void update_fonts(inkray::EditorApp& app, float* font_scale) {
  if (app.ui_scale() == *font_scale) return;
  const bool uploaded = *font_scale != 0.f;
  *font_scale = app.ui_scale();
  std::string warning;
  inkray::set_ui_scale(*font_scale, &warning);
  if (!warning.empty()) app.state().log.warning(warning);
  if (uploaded) {
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
}

}  // namespace

// Dear ImGui's GLFW + OpenGL 3 example loop, with the editor as the one window's
// content and, for tests and measurements, the scripted run's hooks around each frame.
int main(int argc, char** argv) {
  Options opt;
  if (!parse(argc, argv, &opt)) {
    usage();
    return 2;
  }
  if (opt.help) {
    usage();
    return 0;
  }
  glfwSetErrorCallback(
      [](int code, const char* text) { std::fprintf(stderr, "glfw error %d: %s\n", code, text); });
  if (!glfwInit()) {
    std::fprintf(stderr,
                 "inkray: cannot open a window (no display?); use inkray-render for headless renders\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(opt.width, opt.height, "inkray", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "inkray: cannot create an OpenGL 3.3 window\n");
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // panel sizes are the editor's own settings (ui/model/ui_settings.h)
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exit_code = 0;
  {
    inkray::EditorOptions editor_options;
    editor_options.scene = opt.scene;
    editor_options.threads = opt.threads;
    editor_options.input_script = opt.input_script;
    editor_options.offer_recovery = opt.script.interactive();  // a scripted run must not stop at a question
    inkray::EditorApp app(editor_options);
    if (opt.ui_scale > 0.f) app.set_ui_scale_setting(opt.ui_scale);
    glfwSetWindowUserPointer(window, &app);
    glfwSetDropCallback(window, on_drop);
    inkray::ScriptedRun scripted(opt.script);
    float font_scale = 0.f;  // the scale the font atlas was built for

    using clock = std::chrono::steady_clock;
    bool running = scripted.start(app);
    for (int frame = 0; running; ++frame) {
      const auto frame_start = clock::now();
      glfwPollEvents();
      if (glfwWindowShouldClose(window)) {
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        app.request_quit();
      }
      scripted.before_frame(app, frame);
      app.set_content_scale(monitor_scale(window));
      update_fonts(app, &font_scale);

      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      int w = 0, h = 0;
      glfwGetFramebufferSize(window, &w, &h);
      app.frame(float(w), float(h));
      ImGui::Render();
      glViewport(0, 0, w, h);
      glClearColor(0.1f, 0.1f, 0.11f, 1.f);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      const double work_ms = std::chrono::duration<double, std::milli>(clock::now() - frame_start).count();
      glfwSetWindowTitle(window, app.window_title().c_str());

      if (!scripted.after_frame(app, frame, w, h, work_ms)) break;
      glfwSwapBuffers(window);
      if (app.should_quit()) break;
      // Without a vsync (Xvfb) the loop would spin: hold it near 60 Hz, but draw a new
      // image as soon as the renderer has one (at most every 4 ms), so an edit's
      // pixels do not wait for the next tick.
      std::this_thread::sleep_until(frame_start + std::chrono::milliseconds(4));
      app.wait_for_image(frame_start + std::chrono::microseconds(16600));
    }
    exit_code = scripted.exit_code();
  }
  glfwSetWindowUserPointer(window, nullptr);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}
