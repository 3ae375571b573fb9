// A render region restricts passes to its pixels: the rest of the film keeps
// what it had (here nothing), so the editor can refine one area.
#include "core/render/render_session.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace inkray {
namespace {

TEST(RenderRegion, OnlyPixelsInsideTheRegionGetSamples) {
  const auto loaded = load_scene(std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes" / "cornell.json");
  ASSERT_TRUE(loaded.scene);
  SceneDesc d = *loaded.scene;
  // Not a multiple of the tile size, and a region that crosses tile borders.
  d.render.width = 40;
  d.render.height = 36;
  const CompileResult c = compile_scene(d);
  ASSERT_TRUE(c.scene);
  RenderSession session(2);
  session.set_scene(c.scene);
  const int x0 = 10, y0 = 14, x1 = 27, y1 = 33;
  session.set_region(x0, y0, x1, y1);
  const int passes = 3;
  for (int p = 0; p < passes; ++p) ASSERT_TRUE(session.render_pass());
  const Film& film = session.film();
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const bool inside = x >= x0 && x < x1 && y >= y0 && y < y1;
      ASSERT_EQ(film.samples_at(x, y), inside ? uint32_t(passes) : 0u) << x << "," << y;
    }
}

}  // namespace
}  // namespace inkray
