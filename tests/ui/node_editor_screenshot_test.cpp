// The real editor under Xvfb with the node editor open on the graph of
// scenes/graph_toon_rim.json: the node boxes and link ends it reports (screen pixels)
// must not overlap, must sit inside the canvas with every link on its pins, must show
// the pins' and titles' colours in the screenshot, and must match a stored layout
// within 2 pixels. INKRAY_UPDATE_REFERENCES=1 rewrites that layout instead.
#include "core/document/json_io.h"
#include "core/image/image_io.h"
#include "ui/nodes/node_canvas.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

namespace inkray {
namespace {

using testing::run_command;

constexpr int kTolerancePixels = 2;  // against the stored layout: rounding, not redesigns
constexpr int kColorTolerance = 40;  // 8-bit, per channel: pins are small and antialiased

struct Box {
  int x = 0, y = 0, w = 0, h = 0;
};
struct LinkEnds {
  std::string from, to;  // "node.socket"
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
struct Layout {
  Box canvas;
  std::map<std::string, Box> nodes;
  std::vector<LinkEnds> links;
};

Layout parse_layout(const std::string& text) {
  Layout layout;
  std::istringstream in(text);
  std::string kind;
  while (in >> kind) {
    if (kind == "canvas") {
      in >> layout.canvas.x >> layout.canvas.y >> layout.canvas.w >> layout.canvas.h;
    } else if (kind == "node") {
      std::string id;
      Box b;
      in >> id >> b.x >> b.y >> b.w >> b.h;
      layout.nodes[id] = b;
    } else if (kind == "link") {
      LinkEnds l;
      in >> l.from >> l.to >> l.x0 >> l.y0 >> l.x1 >> l.y1;
      layout.links.push_back(l);
    }
  }
  return layout;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The screenshot's 8-bit sRGB value at a pixel.
Rgb8 pixel(const RgbImage& img, int x, int y) {
  const Color& c = img.at(x, y);
  const auto byte = [](float v) {
    return (unsigned char)std::lround(linear_to_srgb(std::clamp(v, 0.f, 1.f)) * 255.f);
  };
  return {byte(c.r), byte(c.g), byte(c.b)};
}

bool near(Rgb8 a, Rgb8 b, int tolerance) {
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
         std::abs(a.b - b.b) <= tolerance;
}

std::string describe(Rgb8 c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

TEST(NodeEditorScreenshot, GraphToonRimLayout) {
  if (const std::string why = testing::editor_unavailable(); !why.empty()) GTEST_SKIP() << why;
  int code = 0;
  const std::string bin = std::string(INKRAY_BINARY_DIR) + "/bin/";
  const std::string scene_file = std::string(INKRAY_SOURCE_DIR) + "/scenes/graph_toon_rim.json";
  const SceneLoadResult loaded = load_scene(scene_file, ReadFor::editing);
  ASSERT_TRUE(loaded.scene) << loaded.errors.at(0);
  const MaterialDesc* material = nullptr;
  for (const MaterialDesc& m : loaded.scene->materials)
    if (!material && std::holds_alternative<GraphDesc>(m.data)) material = &m;
  ASSERT_TRUE(material) << "no graph material in " << scene_file;
  const GraphDesc& graph = std::get<GraphDesc>(material->data);

  // Kept after the run, so a failure can be looked at.
  const auto dir = std::filesystem::path(INKRAY_BINARY_DIR) / "test_output" / "node_editor";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string shot = (dir / "graph_toon_rim.png").string();
  const std::string layout_file = (dir / "graph_toon_rim.layout").string();
  const std::string out =
      run_command("INKRAY_CONFIG_DIR=" + dir.string() + " xvfb-run -a -s '-screen 0 1600x900x24' " + bin +
                      "inkray --screenshot " + shot + " --frames 10 --node-editor " + material->name +
                      " --node-layout " + layout_file + " " + scene_file,
                  &code);
  ASSERT_EQ(code, 0) << out;
  const std::string text = read_text(layout_file);
  const Layout layout = parse_layout(text);
  SCOPED_TRACE("screenshot " + shot + ", layout:\n" + text);

  // Every node, inside the canvas, none over another.
  ASSERT_EQ(layout.nodes.size(), graph.nodes.size());
  const Box& c = layout.canvas;
  for (const auto& [id, b] : layout.nodes) {
    EXPECT_GE(b.x, c.x) << id;
    EXPECT_GE(b.y, c.y) << id;
    EXPECT_LE(b.x + b.w, c.x + c.w) << id;
    EXPECT_LE(b.y + b.h, c.y + c.h) << id;
    EXPECT_GE(b.w, 100) << id << " is too narrow to read";
    for (const auto& [other, o] : layout.nodes) {
      const bool overlap =
          id < other && b.x < o.x + o.w && o.x < b.x + b.w && b.y < o.y + o.h && o.y < b.y + b.h;
      EXPECT_FALSE(overlap) << id << " overlaps " << other;
    }
  }

  RgbImage image;
  std::string error;
  ASSERT_TRUE(read_image(shot, true, &image, &error)) << error;
  // Titles in their category's colour, just right of the left border.
  for (const GraphNodeDesc& n : graph.nodes) {
    const Box& b = layout.nodes.at(n.id);
    const Rgb8 seen = pixel(image, b.x + 3, b.y + 12), want = category_rgb(node_category(n.data));
    EXPECT_TRUE(near(seen, want, 12))
        << n.id << "'s title is " << describe(seen) << ", not " << describe(want);
  }

  // Every link ends on its nodes' edges (outputs right, inputs left), where a pin of its type is drawn.
  ASSERT_EQ(layout.links.size(), graph.links.size());
  for (const LinkEnds& l : layout.links) {
    const std::string from_id = l.from.substr(0, l.from.find('.')), to_id = l.to.substr(0, l.to.find('.'));
    const Box& from = layout.nodes.at(from_id);
    const Box& to = layout.nodes.at(to_id);
    EXPECT_NEAR(l.x0, from.x + from.w, 1) << l.from;
    EXPECT_TRUE(l.y0 > from.y + 20 && l.y0 < from.y + from.h) << l.from;
    EXPECT_NEAR(l.x1, to.x, 1) << l.to;
    EXPECT_TRUE(l.y1 > to.y + 20 && l.y1 < to.y + to.h) << l.to;
    const GraphNodeDesc* node = find_node(graph, from_id);
    ASSERT_TRUE(node);
    const Rgb8 want = socket_rgb(*output_type(node->data, l.from.substr(from_id.size() + 1)));
    for (const auto& [x, y, name] : {std::tuple{l.x0, l.y0, l.from}, std::tuple{l.x1, l.y1, l.to}}) {
      const Rgb8 seen = pixel(image, x, y);
      EXPECT_TRUE(near(seen, want, kColorTolerance))
          << "pin " << name << " is " << describe(seen) << ", not " << describe(want);
    }
  }

  // Against the stored layout, within kTolerancePixels.
  const auto reference =
      std::filesystem::path(INKRAY_SOURCE_DIR) / "tests/ui/data/node_editor_graph_toon_rim.layout";
  if (std::getenv("INKRAY_UPDATE_REFERENCES")) {
    std::filesystem::create_directories(reference.parent_path());
    std::ofstream(reference) << text;
    GTEST_SKIP() << "wrote " << reference;
  }
  ASSERT_TRUE(std::filesystem::exists(reference))
      << reference << " is missing (INKRAY_UPDATE_REFERENCES=1 writes it)";
  const Layout want = parse_layout(read_text(reference));
  const auto close = [](int a, int b) { return std::abs(a - b) <= kTolerancePixels; };
  EXPECT_TRUE(close(want.canvas.x, c.x) && close(want.canvas.y, c.y) && close(want.canvas.w, c.w) &&
              close(want.canvas.h, c.h))
      << "the canvas moved";
  EXPECT_EQ(want.nodes.size(), layout.nodes.size())
      << "the scene changed? INKRAY_UPDATE_REFERENCES=1 updates it";
  for (const auto& [id, w] : want.nodes) {
    const auto it = layout.nodes.find(id);
    ASSERT_NE(it, layout.nodes.end()) << id << " is in the reference but not drawn";
    const Box& b = it->second;
    EXPECT_TRUE(close(w.x, b.x) && close(w.y, b.y) && close(w.w, b.w) && close(w.h, b.h))
        << id << " at " << b.x << " " << b.y << " " << b.w << " " << b.h << ", reference " << w.x << " "
        << w.y << " " << w.w << " " << w.h;
  }
  ASSERT_EQ(want.links.size(), layout.links.size());
  for (size_t i = 0; i < want.links.size(); ++i) {
    const LinkEnds &w = want.links[i], &l = layout.links[i];
    EXPECT_EQ(w.from + " " + w.to, l.from + " " + l.to);
    EXPECT_TRUE(close(w.x0, l.x0) && close(w.y0, l.y0) && close(w.x1, l.x1) && close(w.y1, l.y1))
        << l.from << " -> " << l.to;
  }
}

}  // namespace
}  // namespace inkray
