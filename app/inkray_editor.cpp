// inkray: the editor. GLFW window, OpenGL 3.3 core, Dear ImGui; everything
// else is EditorApp (ui/). Headless runs for tests and measurements:
//   inkray --screenshot OUT.png --frames N [--window-size W H] [--widget-report OUT.txt]
//          [--node-editor MATERIAL --node-layout OUT.txt] [--drop FILE] [SCENE.json]
//   inkray --measure-edits N [--edit KIND,...] [SCENE.json]   (edit latency, frame
//   times and samples kept, per kind of edit)
#include "app/cli_numbers.h"
#include "app/edit_measurement.h"
#include "core/document/json_io.h"
#include "core/image/image_io.h"
#include "core/io/atomic_file.h"
#include "ui/viewport/camera_controller.h"
#include "ui/editor_app.h"
#include "ui/widgets/fonts.h"
#include "ui/widgets/widget_report.h"

#include <GLFW/glfw3.h>
#include <GL/gl.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <type_traits>
#include <vector>

namespace {

struct Options {
  std::string scene;
  std::string screenshot;
  int frames = 0;  // 0: run until closed
  int measure_edits = 0;
  std::vector<inkray::measure::EditKind> edit_kinds;  // empty: camera
  int threads = 0;
  int width = 1600, height = 900;
  std::string select;              // object to select at start, so screenshots show the highlight
  std::string node_material;       // material to open the node editor on
  std::string node_layout;         // where to write the node editor's layout with the screenshot
  std::string widget_report;       // where to write the named widgets' rectangles with the screenshot
  std::vector<std::string> drops;  // files handed to the drop callback after the first frame
  std::string scene_dump;          // where to write the document (JSON) with the screenshot
  std::string input_script;        // keys and mouse moves to play, one a line (ui/editor_app.h)
  std::string export_path;         // export through the dialog to this file, then take the screenshot
  float ui_scale = 0.f;            // overrides the saved interface size when set
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

bool parse(int argc, char** argv, Options* o) {
  // A number in its range, or the message naming the option and what it expected.
  const auto number = [](std::string_view option, const char* text, auto lo, auto hi, auto* out) {
    const std::string problem = inkray::cli::read_option_number(option, text, lo, hi, out);
    if (!problem.empty()) std::fprintf(stderr, "inkray: %s\n", problem.c_str());
    return problem.empty();
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    const char* v = nullptr;
    if (a == "-h" || a == "--help") {
      usage();
      std::exit(0);
    } else if (a == "--screenshot" && (v = value())) {
      o->screenshot = v;
    } else if (a == "--frames" && (v = value())) {
      if (!number("--frames", v, 0, 1000000, &o->frames)) return false;
    } else if (a == "--measure-edits" && (v = value())) {
      if (!number("--measure-edits", v, 1, 100000, &o->measure_edits)) return false;
    } else if (a == "--edit" && (v = value())) {
      const std::string list = v;
      for (size_t begin = 0; begin <= list.size();) {
        const size_t end = std::min(list.find(',', begin), list.size());
        const std::string name = list.substr(begin, end - begin);
        const auto found =
            std::find(inkray::measure::kEditKindNames.begin(), inkray::measure::kEditKindNames.end(), name);
        if (found == inkray::measure::kEditKindNames.end()) {
          std::fprintf(stderr, "inkray: --edit: unknown kind \"%s\" (valid kinds: %s)\n", name.c_str(),
                       inkray::measure::edit_kind_list().c_str());
          std::exit(2);
        }
        o->edit_kinds.push_back(inkray::measure::EditKind(found - inkray::measure::kEditKindNames.begin()));
        begin = end + 1;
      }
    } else if (a == "--threads" && (v = value())) {
      if (!number("--threads", v, 1, 1024, &o->threads)) return false;
    } else if (a == "--select" && (v = value())) {
      o->select = v;
    } else if (a == "--node-editor" && (v = value())) {
      o->node_material = v;
    } else if (a == "--node-layout" && (v = value())) {
      o->node_layout = v;
    } else if (a == "--size" && (v = value())) {
      if (std::sscanf(v, "%dx%d", &o->width, &o->height) != 2) return false;
    } else if (a == "--window-size" && i + 2 < argc) {
      if (!number("--window-size", argv[++i], 64, 16384, &o->width) ||
          !number("--window-size", argv[++i], 64, 16384, &o->height))
        return false;
    } else if (a == "--ui-scale" && (v = value())) {
      if (!number("--ui-scale", v, 0.5f, 3.f, &o->ui_scale)) return false;
    } else if (a == "--widget-report" && (v = value())) {
      o->widget_report = v;
    } else if (a == "--export" && (v = value())) {
      o->export_path = v;
    } else if (a == "--scene-dump" && (v = value())) {
      o->scene_dump = v;
    } else if (a == "--input-script" && (v = value())) {
      o->input_script = v;
    } else if (a == "--drop" && (v = value())) {
      o->drops.emplace_back(v);
    } else if (!a.empty() && a[0] != '-' && o->scene.empty()) {
      o->scene = a;
    } else {
      std::fprintf(stderr, "inkray: unknown or incomplete argument \"%s\"\n", a.c_str());
      return false;
    }
  }
  return true;
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

bool write_screenshot(const std::string& file, int width, int height) {
  std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  inkray::RgbImage image{width, height, std::vector<inkray::Color>(size_t(width) * size_t(height))};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &rgba[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4];  // GL rows go up
      image.at(x, y) =
          inkray::Color(inkray::srgb_to_linear(p[0] / 255.f), inkray::srgb_to_linear(p[1] / 255.f),
                        inkray::srgb_to_linear(p[2] / 255.f));
    }
  }
  std::string error;
  if (!inkray::write_image(file, image, &error)) {
    std::fprintf(stderr, "inkray: %s\n", error.c_str());
    return false;
  }
  return true;
}

bool write_text(const std::string& file, const std::string& text) {
  std::string error;
  if (inkray::write_file_atomically(file, text, &error)) return true;
  std::fprintf(stderr, "inkray: %s\n", error.c_str());
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  if (!parse(argc, argv, &opt)) {
    usage();
    return 2;
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
    // Scripted runs must not stop at a recovery question.
    editor_options.offer_recovery = opt.screenshot.empty() && opt.measure_edits == 0;
    inkray::EditorApp app(editor_options);
    if (opt.ui_scale > 0.f) app.set_ui_scale_setting(opt.ui_scale);
    glfwSetWindowUserPointer(window, &app);
    glfwSetDropCallback(window, on_drop);
    inkray::widget_report::enable(!opt.widget_report.empty());
    float font_scale = 0.f;  // the scale the font atlas was built for
    if (!opt.select.empty()) {
      inkray::EditorState& state = app.state();
      const auto& objects = state.document.scene().objects;
      const auto found = std::find_if(objects.begin(), objects.end(),
                                      [&](const inkray::ObjectDesc& o) { return o.name == opt.select; });
      if (found == objects.end()) {
        std::fprintf(stderr, "inkray: --select: no object named \"%s\"\n", opt.select.c_str());
        exit_code = 1;
      } else {
        state.selection = {inkray::ItemKind::object, int(found - objects.begin())};
      }
    }

    if (!opt.node_material.empty() && exit_code == 0) {
      inkray::EditorState& state = app.state();
      const auto& materials = state.document.scene().materials;
      const auto found = std::find_if(materials.begin(), materials.end(), [&](const inkray::MaterialDesc& m) {
        return m.name == opt.node_material;
      });
      if (found == materials.end()) {
        std::fprintf(stderr, "inkray: --node-editor: no material named \"%s\"\n", opt.node_material.c_str());
        exit_code = 1;
      } else {
        state.selection = {inkray::ItemKind::material, int(found - materials.begin())};
        app.show_node_editor(true);
      }
    }

    std::unique_ptr<inkray::measure::EditMeasurement> measurement;
    bool kind_skipped = false;  // a kind this scene cannot take: measure the rest, then fail
    if (opt.measure_edits > 0 && exit_code == 0) {
      std::vector<inkray::measure::EditKind> kinds;
      for (inkray::measure::EditKind kind :
           opt.edit_kinds.empty() ? std::vector<inkray::measure::EditKind>{inkray::measure::EditKind::camera}
                                  : opt.edit_kinds) {
        if (const std::string why = inkray::measure::unavailable(kind, app.state().document.scene());
            !why.empty()) {
          std::fprintf(stderr, "inkray: --edit %s: %s\n",
                       std::string(inkray::measure::kEditKindNames[size_t(kind)]).c_str(), why.c_str());
          kind_skipped = true;
        } else {
          kinds.push_back(kind);
        }
      }
      if (kinds.empty()) exit_code = 1;
      measurement = std::make_unique<inkray::measure::EditMeasurement>(std::move(kinds), opt.measure_edits);
    }

    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    uint64_t export_id = 0;
    int export_finished_frame = -1;  // the screenshot waits a few frames more: the image view opens
    int frame = 0;
    // A failed --select or --edit leaves exit_code set and skips the loop.
    for (; exit_code == 0; ++frame) {
      const auto frame_start = clock::now();
      glfwPollEvents();
      if (glfwWindowShouldClose(window)) {
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        app.request_quit();
      }
      if (frame == 1) {
        std::vector<const char*> drops;
        for (const auto& d : opt.drops) drops.push_back(d.c_str());
        if (!drops.empty()) on_drop(window, int(drops.size()), drops.data());
      }
      app.set_content_scale(monitor_scale(window));
      if (app.ui_scale() != font_scale) {
        // The atlas is rebuilt between frames; the backend uploads it at its first frame,
        // and again here on later changes.
        const bool uploaded = font_scale != 0.f;
        font_scale = app.ui_scale();
        std::string warning;
        inkray::set_ui_scale(font_scale, &warning);
        if (!warning.empty()) app.state().log.warning(warning);
        if (uploaded) {
          ImGui_ImplOpenGL3_DestroyFontsTexture();
          ImGui_ImplOpenGL3_CreateFontsTexture();
        }
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      inkray::widget_report::begin_frame();
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

      if (!opt.export_path.empty() && frame == 1) {
        export_id = app.export_ui().start_for_test(app.state(), opt.export_path);
        if (export_id == 0) {
          std::fprintf(stderr, "inkray: --export: %s\n", app.export_ui().dialog_error().c_str());
          exit_code = 1;
          break;
        }
      }
      if (export_id != 0 && export_finished_frame < 0) {
        const inkray::ExportEntry* e = app.export_ui().queue().find(export_id);
        if (!e || e->state == inkray::ExportState::done || e->state == inkray::ExportState::failed ||
            e->state == inkray::ExportState::cancelled) {
          export_finished_frame = frame;
          if (!e || e->state != inkray::ExportState::done) {
            std::fprintf(stderr, "inkray: --export: %s\n", e ? e->error.c_str() : "the export vanished");
            exit_code = 1;
            break;
          }
          std::printf("export: %d threads, %u spp in %.2f s\n", e->progress.threads, e->progress.spp,
                      e->progress.elapsed_seconds);
          for (const auto& f : e->written) std::printf("export wrote: %s\n", f.string().c_str());
        }
      }
      const bool export_settled =
          opt.export_path.empty() || (export_finished_frame >= 0 && frame >= export_finished_frame + 5);
      const double seconds = std::chrono::duration<double>(clock::now() - start).count();
      if (!opt.screenshot.empty() && frame >= opt.frames && export_settled &&
          (app.viewport().shown_full_resolution() || seconds > 120.0)) {
        const auto& v = app.viewport_frame();
        std::printf("viewport image: %d %d %d %d\n", int(v.image_x), int(v.image_y), int(v.image_w),
                    int(v.image_h));
        std::printf("viewport spp: %u\n", app.viewport().shown_spp());
        std::printf("viewport denoised: %d\n", app.viewport().shown_denoised() ? 1 : 0);
        std::printf("ui scale: %.2f\n", app.ui_scale());
        exit_code = write_screenshot(opt.screenshot, w, h) ? 0 : 1;
        if (!opt.node_layout.empty() && !write_text(opt.node_layout, app.node_editor().layout()))
          exit_code = 1;
        if (!opt.scene_dump.empty() &&
            !write_text(opt.scene_dump, inkray::scene_to_string(app.state().document.scene()))) {
          exit_code = 1;
        }
        if (!opt.widget_report.empty() &&
            !write_text(opt.widget_report, "window 0 0 " + std::to_string(w) + " " + std::to_string(h) +
                                               "\n" + inkray::widget_report::text())) {
          exit_code = 1;
        }
        break;
      }
      if (measurement && !measurement->step(app, work_ms)) {
        if (measurement->failed() || kind_skipped) exit_code = 1;
        break;
      }
      if (opt.screenshot.empty() && opt.measure_edits == 0 && opt.frames > 0 && frame >= opt.frames) break;
      glfwSwapBuffers(window);
      if (app.should_quit()) break;
      // Without a vsync (Xvfb) the loop would spin: hold it near 60 Hz, but draw a new
      // image as soon as the renderer has one (at most every 4 ms), so an edit's
      // pixels do not wait for the next tick.
      std::this_thread::sleep_until(frame_start + std::chrono::milliseconds(4));
      app.wait_for_image(frame_start + std::chrono::microseconds(16600));
    }
  }
  glfwSetWindowUserPointer(window, nullptr);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}
