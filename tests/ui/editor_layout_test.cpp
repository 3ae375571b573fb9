// The editor at the window sizes artists use (4K at twice the interface size, as its
// monitor scale would give), under Xvfb: every reported control (the viewport's, the
// timeline's and the render panel's toolbars, the right column's tabs, the Line sets
// tab's buttons and rows) lies inside its panel's visible area and inside the window,
// so nothing is cut off or unreachable. Screenshots are kept in the
// test's temporary folder for looking at.
#include "core/image/image_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace inkray {
namespace {

using namespace inkray::testing;

struct Rect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct Widget {
  Rect item, visible;
};

std::map<std::string, Widget> read_report(const std::filesystem::path& file, Rect* window) {
  std::map<std::string, Widget> widgets;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string name;
    words >> name;
    if (name == "window") {
      words >> window->x0 >> window->y0 >> window->x1 >> window->y1;
      continue;
    }
    Widget w;
    words >> w.item.x0 >> w.item.y0 >> w.item.x1 >> w.item.y1 >> w.visible.x0 >> w.visible.y0 >>
        w.visible.x1 >> w.visible.y1;
    if (words) widgets[name] = w;
  }
  return widgets;
}

bool inside(const Rect& a, const Rect& b) {
  constexpr float kSlack = 1.f;  // ImGui rounds item rectangles to pixels
  return a.x0 >= b.x0 - kSlack && a.y0 >= b.y0 - kSlack && a.x1 <= b.x1 + kSlack && a.y1 <= b.y1 + kSlack;
}

struct WindowCase {
  int width, height;
  float ui_scale;  // 4K screens run at twice the interface size
};

class EditorLayout : public ::testing::TestWithParam<WindowCase> {};

// Runs the editor on `scene` at the case's size with `options` added, and checks that
// every control it reported lies inside its panel and the window. The controls' names.
std::map<std::string, Widget> run_and_check(const WindowCase& c, const std::string& test,
                                            const std::string& scene, const std::string& options) {
  const auto [width, height, ui_scale] = c;
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const auto dir = std::filesystem::temp_directory_path() / ("inkray_editor_layout_" + test + "_" + size);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto shot = dir / "editor.png", report = dir / "widgets.txt";
  int code = 0;
  // A fresh config folder: the default panel sizes and interface size.
  const std::string out =
      run_command(editor_command(dir, width, height) + " --ui-scale " + std::to_string(ui_scale) + " " +
                      options + " --screenshot " + shot.string() + " --widget-report " + report.string() +
                      " " + std::string(INKRAY_SOURCE_DIR) + "/scenes/" + scene,
                  &code);
  EXPECT_EQ(code, 0) << out;

  RgbImage image;
  std::string error;
  EXPECT_TRUE(read_image(shot, true, &image, &error)) << error;
  EXPECT_EQ(image.width, width);
  EXPECT_EQ(image.height, height);

  Rect window;
  const auto widgets = read_report(report, &window);
  EXPECT_EQ(window.x1, float(width));
  EXPECT_EQ(window.y1, float(height));
  for (const auto& [name, w] : widgets) {
    EXPECT_TRUE(inside(w.item, w.visible)) << name << " is clipped by its panel at " << size;
    EXPECT_TRUE(inside(w.item, window)) << name << " is outside the window at " << size;
  }
  return widgets;
}

size_t count_starting(const std::map<std::string, Widget>& widgets, const std::string& prefix) {
  size_t n = 0;
  for (const auto& entry : widgets) n += entry.first.rfind(prefix, 0) == 0;
  return n;
}

TEST_P(EditorLayout, EveryToolbarControlIsInsideItsPanel) {
  if (const std::string why = editor_unavailable(); !why.empty()) GTEST_SKIP() << why;
  const auto widgets =
      run_and_check(GetParam(), "toolbars", "toon.json", "--select two_band_ball --frames 10");
  // The toolbars report themselves; a renamed or lost report would make this test vacuous.
  EXPECT_GE(count_starting(widgets, "viewport."), 6u) << "the viewport toolbar reported too few controls";
  EXPECT_GE(count_starting(widgets, "render."), 1u) << "the render panel reported no controls";
  EXPECT_GE(count_starting(widgets, "timeline."), 10u) << "the timeline reported too few controls";
  EXPECT_EQ(count_starting(widgets, "tabs."), 2u) << "the right column's tabs are not reported";
}

// The Line sets tab open on a scene with two sets: its buttons, rows and switches.
TEST_P(EditorLayout, EveryLineSetsControlIsInsideItsPanel) {
  if (const std::string why = editor_unavailable(); !why.empty()) GTEST_SKIP() << why;
  const auto dir = std::filesystem::temp_directory_path() / "inkray_editor_layout_script";
  std::filesystem::create_directories(dir);
  const auto script = dir / ("open_line_sets_" + std::to_string(GetParam().width) + ".txt");
  std::ofstream(script) << "wait 2\nhover tabs.line_sets\nclick\nwait 3\n";
  const auto widgets = run_and_check(GetParam(), "line_sets", "lines_technical.json",
                                     "--threads 1 --frames 30 --input-script " + script.string());
  EXPECT_EQ(count_starting(widgets, "line_sets."), 5u + 2u * 2u) << "buttons, and each set's row and switch";
}

std::string size_name(const ::testing::TestParamInfo<WindowCase>& c) {
  return std::to_string(c.param.width) + "x" + std::to_string(c.param.height);
}

INSTANTIATE_TEST_SUITE_P(Sizes, EditorLayout,
                         ::testing::Values(WindowCase{1280, 720, 1.f}, WindowCase{1920, 1080, 1.f},
                                           WindowCase{2560, 1440, 1.f}, WindowCase{3840, 2160, 2.f}),
                         size_name);

}  // namespace
}  // namespace inkray
