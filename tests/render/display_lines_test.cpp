// The viewport and a written file show the same outlined image for the same
// display: lines are composited for it (core/film/resolve.h), and a change of
// exposure or view transform in the viewport composites them again over the
// samples it has, as a fresh resolve for that display would.
#include "core/film/resolve.h"
#include "core/image/image_io.h"
#include "core/render/progressive_renderer.h"
#include "core/render/render_outputs.h"

#include "tests/support/file_helpers.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

namespace inkray {
namespace {

constexpr int kSpp = 4;

// An outlined light (radiance 20) on black: its silhouette pixels are what
// compositing before the view transform clipped to white.
SceneDesc outlined_light() {
  SceneDesc d = testing::one_sphere_scene(64, 48);
  d.materials[0].data = EmissiveDesc{Color(1.f), 20.f, false};
  d.outlines.enabled = true;
  d.outlines.width = 50.f;  // pixels at 1080 lines: 2.2 here
  d.outlines.silhouette.color = Color(0.f);
  return d;
}

struct FileRender {
  std::shared_ptr<const RenderScene> scene;
  std::unique_ptr<RenderSession> session;
};

FileRender render_for_files(const SceneDesc& d) {
  FileRender r;
  CompileResult c = compile_scene(d);
  EXPECT_TRUE(c.scene);
  r.scene = c.scene;
  r.session = std::make_unique<RenderSession>(2);
  r.session->set_scene(c.scene);
  render_batch(*r.session, {kSpp, 0.0});
  return r;
}

std::shared_ptr<const ViewportSnapshot> next_snapshot(ProgressiveRenderer& renderer, uint64_t after) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  if (!renderer.wait_for_generation(after, give_up)) return nullptr;
  return renderer.latest();
}

// Largest per-channel difference between an RGBA snapshot and RGB bytes.
int max_difference(const std::vector<uint8_t>& rgba, const std::vector<uint8_t>& rgb) {
  int worst = 0;
  for (size_t i = 0; i < rgb.size() / 3; ++i)
    for (size_t k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(int(rgba[4 * i + k]) - int(rgb[3 * i + k])));
  return worst;
}

TEST(DisplayLines, ViewportAndFileShowTheSamePixels) {
  const SceneDesc d = outlined_light();
  ProgressiveRenderer renderer(2);
  renderer.set_limits({kSpp, 0.0, 0.0});
  const uint64_t revision = renderer.submit(d);
  std::shared_ptr<const ViewportSnapshot> shown;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < give_up) {
    shown = renderer.latest();
    if (shown && shown->revision == revision && shown->finished) break;
    renderer.wait_for_generation(renderer.generation(),
                                 std::chrono::steady_clock::now() + std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(shown && shown->finished);

  // The file: what inkray-render writes, read back.
  const FileRender files = render_for_files(d);
  testing::ScratchFolder folder;
  std::string error;
  ASSERT_EQ(write_render_outputs(*files.session, folder / "light.png", {}, &error), OutputsWritten::all)
      << error;
  RgbImage png;
  ASSERT_TRUE(read_image(folder / "light.png", false, &png, &error)) << error;
  std::vector<uint8_t> png_bytes;
  for (const Color& c : png.pixels)
    for (int k = 0; k < 3; ++k) png_bytes.push_back(uint8_t(std::lround(c[k] * 255.f)));
  // The viewport encodes sRGB through a table: within one step of the exact encoding.
  EXPECT_LE(max_difference(shown->rgba, png_bytes), 1);

  // The silhouette is drawn over the light: grey pixels, not a clipped white.
  int grey = 0;
  for (size_t i = 0; i < png_bytes.size(); i += 3) grey += png_bytes[i] > 40 && png_bytes[i] < 215;
  EXPECT_GT(grey, 20);

  // New displays: the viewport composites the lines again over the same samples.
  const Film& film = files.session->film();
  for (const DisplayEncoding& display :
       {DisplayEncoding{-1.5f, ViewTransform::standard}, DisplayEncoding{1.f, ViewTransform::filmic},
        DisplayEncoding{0.5f, ViewTransform::raw}}) {
    SCOPED_TRACE(std::string(kViewTransformNames[size_t(display.transform)]) + " " +
                 std::to_string(display.exposure));
    const RgbImage fresh = resolve_final(film, *files.scene, display);
    const std::vector<uint8_t> expected = encode_display(fresh, display);
    uint64_t seen = renderer.generation();
    ViewportView view;
    view.encoding = display;
    renderer.set_view(view);
    // A snapshot published just before the change may still arrive first: wait
    // for the one made for this display.
    std::shared_ptr<const ViewportSnapshot> now;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < until) {
      now = next_snapshot(renderer, seen);
      if (!now || now->rgba == expected) break;
      seen = renderer.generation();
    }
    ASSERT_TRUE(now);
    EXPECT_EQ(now->accumulation, shown->accumulation) << "a display change restarted the film";
    EXPECT_EQ(now->stats.spp, shown->stats.spp);
    EXPECT_EQ(now->rgba, expected);
    if (display.transform == ViewTransform::standard) {
      EXPECT_LE(max_difference(now->rgba, encode_srgb8(fresh, display.exposure)), 1);
    }
  }
}

}  // namespace
}  // namespace inkray
