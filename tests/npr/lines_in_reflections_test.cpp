// outlines.in_reflections decides whether lines are followed into mirrors: on
// scenes/mirror_ball_outlines.json the lines seen in the mirror ball go with it, and the
// lines drawn on the surfaces seen directly stay.
#include "core/document/json_io.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace inkray {
namespace {

// Line opacity summed inside and outside the mirror ball's disc on screen.
struct LineCoverage {
  double in_mirror = 0.0, elsewhere = 0.0;
};

LineCoverage coverage(bool in_reflections) {
  SceneLoadResult loaded =
      load_scene(std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes/mirror_ball_outlines.json");
  EXPECT_TRUE(loaded.scene);
  SceneDesc d = *loaded.scene;
  d.render.width = 192;
  d.render.height = 108;
  d.outlines.in_reflections = in_reflections;
  AovSet aovs;
  aovs.add(Aov::outline);
  aovs.add(Aov::object_id);
  const testing::RenderedFilm film = testing::render_film(d, 4, aovs);
  const RgbImage lines = film.aov(Aov::outline), ids = film.aov(Aov::object_id);
  // The mirror ball is objects[1]; a pixel well inside its disc has its id on every
  // neighbour, so its own silhouette line does not count as a line in the mirror.
  const auto mirror_inside = [&](int x, int y) {
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx) {
        const int xx = std::clamp(x + dx, 0, lines.width - 1), yy = std::clamp(y + dy, 0, lines.height - 1);
        if (ids.at(xx, yy).r != 1.f) return false;
      }
    return true;
  };
  LineCoverage c;
  for (int y = 0; y < lines.height; ++y)
    for (int x = 0; x < lines.width; ++x)
      (mirror_inside(x, y) ? c.in_mirror : c.elsewhere) += lines.at(x, y).r;
  return c;
}

TEST(LinesInReflections, TheMirrorShowsLinesOnlyWhenAsked) {
  const LineCoverage on = coverage(true), off = coverage(false);
  EXPECT_GT(on.in_mirror, 10.0) << "the boxes and balls reflected in the mirror have lines";
  EXPECT_LT(off.in_mirror, 0.1 * on.in_mirror) << "without in_reflections the mirror shows none";
  EXPECT_NEAR(off.elsewhere, on.elsewhere, 0.15 * on.elsewhere) << "lines seen directly stay";
}

}  // namespace
}  // namespace inkray
