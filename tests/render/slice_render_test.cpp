// Slices of the sample sequence and crop windows of the image render exactly
// what one render of every pass and pixel renders: adaptive line sampling's
// decisions are traced again or counted, and the film's double sums add up
// without rounding, so the merged film is the same to the last bit.
#include "core/document/json_io.h"
#include "core/film/film_partial.h"
#include "core/render/render_outputs.h"
#include "core/render/render_session.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

namespace inkray {
namespace {

SceneDesc outlined_box(int width, int height) {
  const auto loaded =
      load_scene(std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes" / "cornell_outlines.json");
  EXPECT_TRUE(loaded.scene);
  SceneDesc d = *loaded.scene;
  d.render.width = width;
  d.render.height = height;
  d.render.max_depth = 6;
  return d;
}

AovSet some_aovs() {
  AovSet a;
  a.add(Aov::albedo);
  a.add(Aov::depth);
  a.add(Aov::object_id);
  return a;
}

// The first pixel where two films' raw state differs, or "".
std::string film_difference(const Film& a, const Film& b, const PixelWindow& w) {
  for (int y = w.y0; y < w.y1; ++y)
    for (int x = w.x0; x < w.x1; ++x) {
      const FilmPixel p = a.pixel(x, y), q = b.pixel(x, y);
      const LineSums &l = p.lines, &m = q.lines;
      const bool same = p.sum == q.sum && p.count == q.count && p.albedo_sum == q.albedo_sum &&
                        p.depth_sum == q.depth_sum && p.hit_count == q.hit_count &&
                        p.object_id == q.object_id && l.coverage == m.coverage && l.weight == m.weight &&
                        l.override_weight == m.override_weight && l.override_color == m.override_color &&
                        l.rays == m.rays && l.hit_rays == m.hit_rays && p.line_count == q.line_count;
      if (!same) return "pixel (" + std::to_string(x) + "," + std::to_string(y) + ")";
    }
  return "";
}

// Renders passes [first, end) of `window` (empty: the whole image) and adds them to
// `into`, reading the line decisions from `decided` when given.
void render_slice(const std::shared_ptr<const RenderScene>& scene, uint32_t first, uint32_t end,
                  const PixelWindow& window, Film& into, const LineDecisions* decided = nullptr) {
  RenderSession s(2);
  s.set_scene(scene, some_aovs());
  s.set_region(window);
  s.continue_from(first, first, {}, decided);
  for (uint32_t p = first; p < end; ++p) ASSERT_TRUE(s.render_pass());
  const PixelWindow w = window.empty() ? PixelWindow{0, 0, into.width(), into.height()} : window;
  for (int y = w.y0; y < w.y1; ++y)
    for (int x = w.x0; x < w.x1; ++x) into.add_pixel(x, y, s.film().pixel(x, y));
}

// A session that rendered passes [0, passes) of the whole image.
std::unique_ptr<RenderSession> render_whole(const std::shared_ptr<const RenderScene>& scene,
                                            uint32_t passes) {
  auto one = std::make_unique<RenderSession>(2);
  one->set_scene(scene, some_aovs());
  for (uint32_t p = 0; p < passes; ++p) EXPECT_TRUE(one->render_pass());
  return one;
}

// The merged film holds the one render's raw state, image and line opacity.
void expect_same_film(const Film& one, const Film& merged, const std::string& label = {}) {
  EXPECT_EQ(film_difference(one, merged, {0, 0, one.width(), one.height()}), "") << label;
  EXPECT_EQ(one.resolve().pixels, merged.resolve().pixels) << label;
  EXPECT_EQ(one.resolve_aov(Aov::outline).pixels, merged.resolve_aov(Aov::outline).pixels) << label;
}

TEST(SliceRender, SlicesAddUpToTheFilmOfOneRender) {
  for (const bool adaptive : {true, false}) {
    SceneDesc d = outlined_box(40, 30);
    d.outlines.adaptive = adaptive;
    const CompileResult c = compile_scene(d);
    ASSERT_TRUE(c.scene);
    const auto one = render_whole(c.scene, 40);
    ASSERT_TRUE(one->film().has_lines());

    // Cut inside the probes, while pixels near lines decide, and after.
    Film merged(40, 30, some_aovs(), true);
    render_slice(c.scene, 0, 3, {}, merged);
    render_slice(c.scene, 3, 11, {}, merged);
    render_slice(c.scene, 11, 29, {}, merged);
    render_slice(c.scene, 29, 40, {}, merged);
    expect_same_film(one->film(), merged, adaptive ? "adaptive" : "full sampling");
  }
}

// A larger image: lines cross tile edges in many places, so what a slice replays
// near a tile reads its neighbours' probes (line_sampling.h, line_reach).
TEST(SliceRender, SlicesOfALargerImageAddUpToTheFilmOfOneRender) {
  const CompileResult c = compile_scene(outlined_box(96, 96));
  ASSERT_TRUE(c.scene);
  const auto one = render_whole(c.scene, 24);
  Film merged(96, 96, some_aovs(), true);
  render_slice(c.scene, 0, 5, {}, merged);
  render_slice(c.scene, 5, 13, {}, merged);
  render_slice(c.scene, 13, 24, {}, merged);
  expect_same_film(one->film(), merged);
}

// Slices that read the decisions made once (decide_lines) instead of tracing them
// again: the same film, for the whole image and for crop windows; a slice that starts
// before the decisions were all made traces them as before.
TEST(SliceRender, SlicesReadingTheLineDecisionsAddUpToTheFilmOfOneRender) {
  const CompileResult c = compile_scene(outlined_box(64, 48));
  ASSERT_TRUE(c.scene);
  RenderSession maker(2);
  maker.set_scene(c.scene, some_aovs());
  const LineDecisions decided = maker.decide_lines();
  ASSERT_EQ(decided.width, 64);
  ASSERT_EQ(decided.rays.size(), size_t(64 * 48));
  EXPECT_GE(decided.decided_at, kLineProbeSamples);
  EXPECT_LT(decided.decided_at, 30u);
  EXPECT_TRUE(std::any_of(decided.kinds.begin(), decided.kinds.end(),
                          [](LineKind k) { return k == LineKind::edge; }));
  EXPECT_TRUE(std::any_of(decided.kinds.begin(), decided.kinds.end(),
                          [](LineKind k) { return k == LineKind::quiet; }));
  const uint32_t passes = decided.decided_at + 14;
  const auto one = render_whole(c.scene, passes);
  // The session that made them renders from pass 0 as a fresh one does.
  for (uint32_t p = 0; p < passes; ++p) ASSERT_TRUE(maker.render_pass());
  EXPECT_EQ(film_difference(one->film(), maker.film(), {0, 0, 64, 48}), "");

  const uint32_t cut = decided.decided_at + 3;
  Film merged(64, 48, some_aovs(), true);
  render_slice(c.scene, 0, 2, {}, merged, &decided);  // before the decisions: traced
  render_slice(c.scene, 2, cut, {}, merged, &decided);
  render_slice(c.scene, cut, cut + 5, {}, merged, &decided);
  render_slice(c.scene, cut + 5, passes, {0, 0, 64, 20}, merged, &decided);
  render_slice(c.scene, cut + 5, passes, {0, 20, 64, 48}, merged, &decided);
  expect_same_film(one->film(), merged);
}

TEST(SliceRender, CropWindowsAddUpToTheFilmOfOneRender) {
  const CompileResult c = compile_scene(outlined_box(40, 30));
  ASSERT_TRUE(c.scene);
  const auto one = render_whole(c.scene, 24);

  // Windows across tile borders; each line map reads the probes around its window.
  Film merged(40, 30, some_aovs(), true);
  for (const PixelWindow& w : {PixelWindow{0, 0, 13, 11}, PixelWindow{13, 0, 40, 11},
                               PixelWindow{0, 11, 29, 30}, PixelWindow{29, 11, 40, 30}}) {
    render_slice(c.scene, 0, 9, w, merged);
    render_slice(c.scene, 9, 24, w, merged);
  }
  expect_same_film(one->film(), merged);
}

// A checkpoint written when the time limit cut a pass holds that pass's finished
// tiles; resumed from the file, the render ends with the film of one never cut.
TEST(SliceRender, ResumesACheckpointCutMidPass) {
  const CompileResult c = compile_scene(outlined_box(64, 48));
  ASSERT_TRUE(c.scene);
  const auto file = std::filesystem::temp_directory_path() / "inkray_slice_render_checkpoint.exr";
  bool cut = false;
  for (int attempt = 0; attempt < 40 && !cut; ++attempt) {
    RenderSession s(2);
    s.set_scene(c.scene, some_aovs());
    for (int p = 0; p < 6; ++p) ASSERT_TRUE(s.render_pass());
    std::thread canceller([&] {
      std::this_thread::sleep_for(std::chrono::microseconds(100 + 150 * attempt));
      s.cancel();
    });
    const bool finished = s.render_pass();
    canceller.join();
    const auto& t = s.tiles_done();
    const auto done = std::count(t.begin(), t.end(), uint8_t(1));
    if (finished || done == 0 || size_t(done) == t.size()) continue;
    cut = true;
    const PartialInfo info{64, 48, {0, 0, 64, 48}, 0, s.stats().passes, t, 1.f, 0, "{}", some_aovs(), true,
                           0,  {}};
    std::string error;
    ASSERT_TRUE(write_partial_file(s.film(), info, file, &error)) << error;
  }
  if (!cut) GTEST_SKIP() << "no pass was cut part way";

  PartialInfo info;
  std::unique_ptr<Film> film;
  std::string error;
  ASSERT_TRUE(read_partial(file, &info, &film, &error)) << error;
  std::filesystem::remove(file);
  EXPECT_EQ(info.end_pass, 6u);
  RenderSession resumed(2);
  resumed.set_scene(c.scene, some_aovs());
  resumed.load_film(*film);
  resumed.continue_from(info.first_pass, info.end_pass, info.tiles_done);
  while (resumed.stats().passes < 10) ASSERT_TRUE(resumed.render_pass());

  RenderSession one(2);
  one.set_scene(c.scene, some_aovs());
  for (int p = 0; p < 10; ++p) ASSERT_TRUE(one.render_pass());
  EXPECT_EQ(film_difference(one.film(), resumed.film(), {0, 0, 64, 48}), "");
}

}  // namespace
}  // namespace inkray
