// The SVG a render writes holds the lines the film found: its outlines, filled at the
// image's pixels, against the line-opacity AOV, with a pixel of tolerance, overall and
// inside the mirror ball (lines seen in a mirror exported as vectors).
#include "core/document/json_io.h"
#include "core/render/render_outputs.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace inkray {
namespace {

using Ring = std::vector<Vec2>;

// Every path's rings, from the "M x y L x y ... Z" the writer uses.
std::vector<std::vector<Ring>> svg_paths(const std::string& svg) {
  std::vector<std::vector<Ring>> paths;
  for (size_t at = svg.find("<path d=\""); at != std::string::npos; at = svg.find("<path d=\"", at + 1)) {
    const size_t start = at + 9, end = svg.find('"', start);
    std::istringstream in(svg.substr(start, end - start));
    std::vector<Ring> rings;
    char op = 0;
    while (in >> op) {
      if (op == 'Z') continue;
      float x = 0.f, y = 0.f;
      in >> x >> y;
      if (op == 'M') rings.emplace_back();
      if (!rings.empty()) rings.back().push_back({x, y});
    }
    paths.push_back(std::move(rings));
  }
  return paths;
}

// Pixels whose centre a path covers (non-zero winding, as SVG fills by default).
std::vector<uint8_t> fill(const std::vector<std::vector<Ring>>& paths, int w, int h) {
  std::vector<uint8_t> covered(size_t(w) * size_t(h), 0);
  for (const auto& rings : paths) {
    float y0 = 1e9f, y1 = -1e9f;
    for (const Ring& r : rings)
      for (Vec2 p : r) y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    for (int y = std::max(0, int(y0)); y <= std::min(h - 1, int(y1)); ++y) {
      const float cy = float(y) + 0.5f;
      std::vector<std::pair<float, int>> crossings;
      for (const Ring& r : rings)
        for (size_t i = 0; i < r.size(); ++i) {
          const Vec2 a = r[i], b = r[(i + 1) % r.size()];
          if ((a.y <= cy) == (b.y <= cy)) continue;
          crossings.push_back({a.x + (cy - a.y) / (b.y - a.y) * (b.x - a.x), b.y > a.y ? 1 : -1});
        }
      std::sort(crossings.begin(), crossings.end());
      int winding = 0;
      for (size_t k = 0; k + 1 < crossings.size(); ++k) {
        winding += crossings[k].second;
        if (winding == 0) continue;
        for (int x = std::max(0, int(std::ceil(crossings[k].first - 0.5f)));
             x < std::min(w, int(std::ceil(crossings[k + 1].first - 0.5f))); ++x)
          covered[size_t(y) * size_t(w) + size_t(x)] = 1;
      }
    }
  }
  return covered;
}

// The share of `a`'s pixels (within `mask`) that have a pixel of `b` within one pixel.
double share_near(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b,
                  const std::vector<uint8_t>& mask, int w, int h) {
  size_t n = 0, near = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      if (!a[i] || !mask[i]) continue;
      ++n;
      bool found = false;
      for (int dy = -1; dy <= 1 && !found; ++dy)
        for (int dx = -1; dx <= 1 && !found; ++dx) {
          const int nx = x + dx, ny = y + dy;
          found = nx >= 0 && ny >= 0 && nx < w && ny < h && b[size_t(ny) * size_t(w) + size_t(nx)];
        }
      near += found;
    }
  return n ? double(near) / double(n) : 1.0;
}

TEST(SvgLines, MatchTheLineOpacityOverallAndInsideTheMirror) {
  const SceneLoadResult loaded =
      load_scene(std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes/mirror_ball_outlines.json");
  ASSERT_TRUE(loaded.scene);
  SceneDesc d = *loaded.scene;
  d.render.width = 480;
  d.render.height = 270;
  AovSet aovs;
  aovs.add(Aov::object_id);
  const testing::RenderedFilm r = testing::render_film(d, 16, aovs);
  ASSERT_TRUE(r.scene);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "inkray_svg_recall";
  std::filesystem::create_directories(dir);
  LineFiles files;
  files.svg = dir / "lines.svg";
  std::string error;
  ASSERT_EQ(write_render_outputs(*r.session, dir / "image.png", {}, &error, {}, {}, nullptr, files),
            OutputsWritten::all)
      << error;
  std::ifstream in(files.svg);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const int w = d.render.width, h = d.render.height;
  const std::vector<uint8_t> drawn = fill(svg_paths(svg), w, h);
  const RgbImage outline = r.aov(Aov::outline), ids = r.aov(Aov::object_id);
  std::vector<uint8_t> found(drawn.size()), all(drawn.size(), 1), mirror(drawn.size());
  int mirror_id = -1;
  for (size_t i = 0; i < d.objects.size(); ++i)
    if (d.objects[i].name == "mirror_ball") mirror_id = int(i);
  ASSERT_GE(mirror_id, 0);
  size_t in_mirror = 0;
  for (size_t i = 0; i < drawn.size(); ++i) {
    found[i] = outline.pixels[i].r >= 0.5f;
    mirror[i] = int(ids.pixels[i].r) == mirror_id;
    // Inside the ball: away from its own silhouette, so only reflected lines count.
    in_mirror += found[i] && mirror[i];
  }
  std::vector<uint8_t> inner(mirror);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx) {
          const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
          if (!mirror[size_t(ny) * size_t(w) + size_t(nx)]) inner[size_t(y) * size_t(w) + size_t(x)] = 0;
        }
  const double recall = share_near(found, drawn, all, w, h), precision = share_near(drawn, found, all, w, h);
  const double mirror_recall = share_near(found, drawn, inner, w, h);
  const double mirror_precision = share_near(drawn, found, inner, w, h);
  std::printf(
      "[ info ] recall %.3f precision %.3f; inside the mirror recall %.3f precision %.3f (%zu line pixels)\n",
      recall, precision, mirror_recall, mirror_precision, in_mirror);
  EXPECT_GT(in_mirror, 100u);
  EXPECT_GE(recall, 0.8);
  EXPECT_GE(precision, 0.8);
  EXPECT_GE(mirror_recall, 0.8);
  EXPECT_GE(mirror_precision, 0.8);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace inkray
