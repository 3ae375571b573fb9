// inkray: the editor. GLFW window, OpenGL 3.3 core, Dear ImGui; everything
// else is EditorApp (ui/). Headless runs for tests and measurements:
//   inkray --screenshot OUT.png --frames N [--node-editor MATERIAL --node-layout OUT.txt] [SCENE.json]
//   inkray --measure-edits N [--edit KIND,...] [SCENE.json]   (edit latency, frame
//   times and samples kept, per kind of edit)
#include "app/edit_measurement.h"
#include "core/image/image_io.h"
#include "core/io/atomic_file.h"
#include "ui/camera_controller.h"
#include "ui/editor_app.h"

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
  std::string select;  // object to select at start, so screenshots show the highlight
  std::string node_material;  // material to open the node editor on
  std::string node_layout;    // where to write the node editor's layout with the screenshot
};

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
      "                       (hue_jitter of the first stroke emitter), exposure (the viewport's)\n"
      "  --threads N          viewport render threads (default: all cores but one)\n"
      "  --size WxH           window size (default 1600x900)\n"
      "  --select NAME        select the object NAME at start (for screenshots and tests)\n"
      "  --node-editor NAME   select the material NAME and open the node editor on it\n"
      "  --node-layout FILE   with --screenshot: write the node editor's node boxes and link ends\n"
      "                       (screen pixels) to FILE");
}

bool parse(int argc, char** argv, Options* o) {
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
      o->frames = std::atoi(v);
    } else if (a == "--measure-edits" && (v = value())) {
      o->measure_edits = std::atoi(v);
    } else if (a == "--edit" && (v = value())) {
      const std::string list = v;
      for (size_t begin = 0; begin <= list.size();) {
        const size_t end = std::min(list.find(',', begin), list.size());
        const std::string name = list.substr(begin, end - begin);
        const auto found = std::find(inkray::measure::kEditKindNames.begin(), inkray::measure::kEditKindNames.end(), name);
        if (found == inkray::measure::kEditKindNames.end()) {
          std::fprintf(stderr, "inkray: --edit: unknown kind \"%s\" (valid kinds: %s)\n", name.c_str(),
                       inkray::measure::edit_kind_list().c_str());
          std::exit(2);
        }
        o->edit_kinds.push_back(inkray::measure::EditKind(found - inkray::measure::kEditKindNames.begin()));
        begin = end + 1;
      }
    } else if (a == "--threads" && (v = value())) {
      o->threads = std::atoi(v);
    } else if (a == "--select" && (v = value())) {
      o->select = v;
    } else if (a == "--node-editor" && (v = value())) {
      o->node_material = v;
    } else if (a == "--node-layout" && (v = value())) {
      o->node_layout = v;
    } else if (a == "--size" && (v = value())) {
      if (std::sscanf(v, "%dx%d", &o->width, &o->height) != 2) return false;
    } else if (!a.empty() && a[0] != '-' && o->scene.empty()) {
      o->scene = a;
    } else {
      std::fprintf(stderr, "inkray: unknown or incomplete argument \"%s\"\n", a.c_str());
      return false;
    }
  }
  return true;
}

bool write_screenshot(const std::string& file, int width, int height) {
  std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  inkray::RgbImage image{width, height, std::vector<inkray::Color>(size_t(width) * size_t(height))};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &rgba[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4];  // GL rows go up
      image.at(x, y) = inkray::Color(inkray::srgb_to_linear(p[0] / 255.f), inkray::srgb_to_linear(p[1] / 255.f),
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
  glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "glfw error %d: %s\n", code, text); });
  if (!glfwInit()) {
    std::fprintf(stderr, "inkray: cannot open a window (no display?); use inkray-render for headless renders\n");
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
  io.IniFilename = nullptr;  // the layout is fixed; nothing to remember
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.f;
  style.FrameRounding = 3.f;
  style.WindowBorderSize = 1.f;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exit_code = 0;
  {
    inkray::EditorOptions editor_options;
    editor_options.scene = opt.scene;
    editor_options.threads = opt.threads;
    // Scripted runs must not stop at a recovery question.
    editor_options.offer_recovery = opt.screenshot.empty() && opt.measure_edits == 0;
    inkray::EditorApp app(editor_options);
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
      const auto found = std::find_if(materials.begin(), materials.end(),
                                      [&](const inkray::MaterialDesc& m) { return m.name == opt.node_material; });
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
           opt.edit_kinds.empty() ? std::vector<inkray::measure::EditKind>{inkray::measure::EditKind::camera} : opt.edit_kinds) {
        if (const std::string why = inkray::measure::unavailable(kind, app.state().document.scene()); !why.empty()) {
          std::fprintf(stderr, "inkray: --edit %s: %s\n", std::string(inkray::measure::kEditKindNames[size_t(kind)]).c_str(),
                       why.c_str());
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
    int frame = 0;
    // A failed --select or --edit leaves exit_code set and skips the loop.
    for (; exit_code == 0; ++frame) {
      const auto frame_start = clock::now();
      glfwPollEvents();
      if (glfwWindowShouldClose(window)) {
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        app.request_quit();
      }
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

      const double seconds = std::chrono::duration<double>(clock::now() - start).count();
      if (!opt.screenshot.empty() && frame >= opt.frames &&
          (app.viewport().shown_full_resolution() || seconds > 120.0)) {
        const auto& v = app.viewport_frame();
        std::printf("viewport image: %d %d %d %d\n", int(v.image_x), int(v.image_y), int(v.image_w),
                    int(v.image_h));
        std::printf("viewport spp: %u\n", app.viewport().shown_spp());
        exit_code = write_screenshot(opt.screenshot, w, h) ? 0 : 1;
        if (!opt.node_layout.empty() && !write_text(opt.node_layout, app.node_editor().layout())) exit_code = 1;
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
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}
