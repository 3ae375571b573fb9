// The editor's renderer under the calls a UI makes: start, edit, pause, region and
// sample limit one at a time, then a storm of all of them at once, which must end in
// the very image a fresh renderer makes of the last document, without leaking.
#include "core/render/progressive_renderer.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <thread>

#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define INKRAY_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define INKRAY_TEST_ASAN 1
#endif
#endif

namespace inkray {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;
using Snapshot = std::shared_ptr<const ViewportSnapshot>;

// A sphere on a ground quad under a point light and a sky, with outlines: every edit
// of the storm changes pixels.
SceneDesc lit_scene(int width, int height) {
  SceneDesc d = testing::one_sphere_scene(width, height);
  d.render.max_depth = 4;
  d.camera.look_from = Point3(0.f, 1.f, 5.f);
  d.materials.push_back({"ground", DiffuseDesc{Color(0.5f)}, {}});
  ObjectDesc ground;
  ground.name = "ground";
  ground.material = "ground";
  ground.shape = QuadDesc{Point3(-4.f, -1.f, 4.f), Vec3(8.f, 0.f, 0.f), Vec3(0.f, 0.f, -8.f)};
  d.objects.push_back(ground);
  d.lights = {{"lamp", PointLightDesc{Point3(2.f, 3.f, 2.f), Color(1.f), 20.f}}};
  d.environment = GradientEnvironmentDesc{};
  d.outlines.enabled = true;
  return d;
}

// Polls the newest snapshot until `done` holds for it; null after `timeout`.
Snapshot wait_for(const ProgressiveRenderer& renderer,
                  const std::function<bool(const ViewportSnapshot&)>& done,
                  std::chrono::seconds timeout = 60s) {
  const auto give_up = Clock::now() + timeout;
  while (Clock::now() < give_up) {
    if (Snapshot s = renderer.latest(); s && done(*s)) return s;
    std::this_thread::sleep_for(1ms);
  }
  return nullptr;
}

Snapshot wait_finished(const ProgressiveRenderer& renderer, uint64_t revision,
                       std::chrono::seconds timeout = 60s) {
  return wait_for(
      renderer, [&](const ViewportSnapshot& s) { return s.revision == revision && s.finished; }, timeout);
}

size_t resident_bytes() {
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  return size_t(resident) * size_t(::sysconf(_SC_PAGESIZE));
}

TEST(ProgressiveRendererLife, StartsAtAPreviewAndRefinesToFullResolution) {
  // Passes of 1024 bounces: the full-resolution one takes long enough that polling
  // cannot miss every preview, which on a light scene all land within a millisecond.
  ProgressiveRenderer renderer(2);
  renderer.set_limits({1, 0.0, 0.0});
  const uint64_t revision = renderer.submit(testing::white_room_scene(64, 48));
  const Snapshot first = wait_for(renderer, [](const ViewportSnapshot&) { return true; });
  ASSERT_TRUE(first);
  EXPECT_EQ(first->revision, revision);
  EXPECT_GT(first->divisor, 1);
  EXPECT_LT(first->width, 64);
  EXPECT_EQ(first->rgba.size(), size_t(first->width) * size_t(first->height) * 4);

  const Snapshot done = wait_finished(renderer, revision);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->divisor, 1);
  EXPECT_EQ(done->width, 64);
  EXPECT_EQ(done->height, 48);
  EXPECT_EQ(done->stats.spp, 1u);
}

TEST(ProgressiveRendererLife, AnEditIsShownAndTheOldRevisionNeverAgain) {
  ProgressiveRenderer renderer(2);
  renderer.set_limits({2, 0.0, 0.0});
  SceneDesc scene = lit_scene(48, 32);
  const Snapshot before = wait_finished(renderer, renderer.submit(scene));
  ASSERT_TRUE(before);

  scene.materials[0].data = DiffuseDesc{Color(0.9f, 0.1f, 0.1f)};
  const uint64_t edited = renderer.submit(scene);
  uint64_t newest = 0;
  const Snapshot after = wait_for(renderer, [&](const ViewportSnapshot& s) {
    EXPECT_GE(s.revision, newest) << "an older revision came back";
    newest = s.revision;
    return s.revision == edited && s.finished;
  });
  ASSERT_TRUE(after);
  EXPECT_NE(after->rgba, before->rgba);
}

TEST(ProgressiveRendererLife, PausedPublishesNothingAndResumes) {
  ProgressiveRenderer renderer(2);
  renderer.set_limits({100000, 0.0, 0.0});
  const uint64_t revision = renderer.submit(lit_scene(48, 32));
  ASSERT_TRUE(wait_for(renderer,
                       [&](const ViewportSnapshot& s) { return s.revision == revision && s.divisor == 1; }));

  renderer.set_paused(true);
  EXPECT_TRUE(renderer.paused());
  // A pass in flight lands and publishes; then the worker sleeps however slow it runs.
  ASSERT_TRUE(renderer.wait_until_idle(Clock::now() + 60s));
  const uint64_t paused_at = renderer.generation();
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(renderer.generation(), paused_at);

  renderer.set_paused(false);
  EXPECT_FALSE(renderer.paused());
  const auto give_up = Clock::now() + 10s;
  while (renderer.generation() == paused_at && Clock::now() < give_up) std::this_thread::sleep_for(1ms);
  EXPECT_GT(renderer.generation(), paused_at);
}

TEST(ProgressiveRendererLife, ARegionRestartKeepsThePixelsOutsideIt) {
  ProgressiveRenderer renderer(2);
  renderer.set_limits({2, 0.0, 0.0});
  const Snapshot whole = wait_finished(renderer, renderer.submit(lit_scene(48, 32)));
  ASSERT_TRUE(whole);

  const uint64_t generation = renderer.generation();
  const RegionRect region{0.25f, 0.25f, 0.75f, 0.5f};
  renderer.set_region(region);
  const Snapshot after =
      wait_for(renderer, [&](const ViewportSnapshot&) { return renderer.generation() > generation; });
  ASSERT_TRUE(after);
  const Snapshot done = wait_for(renderer, [](const ViewportSnapshot& s) { return s.finished; });
  ASSERT_TRUE(done);
  ASSERT_EQ(done->width, whole->width);
  ASSERT_EQ(done->height, whole->height);
  const int x0 = int(region.x0 * 48.f), x1 = int(region.x1 * 48.f);
  const int y0 = int(region.y0 * 32.f), y1 = int(region.y1 * 32.f);
  int changed = 0, black = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 48; ++x) {
      if (x >= x0 && x < x1 && y >= y0 && y < y1) continue;
      const size_t i = (size_t(y) * 48 + size_t(x)) * 4;
      changed += std::memcmp(&done->rgba[i], &whole->rgba[i], 4) != 0;
      black += done->rgba[i] == 0 && done->rgba[i + 1] == 0 && done->rgba[i + 2] == 0;
    }
  }
  EXPECT_EQ(changed, 0) << "pixels outside the region changed after the region restart (" << black
                        << " of them to black: the restart cleared the film)";
}

TEST(ProgressiveRendererLife, FinishesAtTheSampleLimitThenIdles) {
  ProgressiveRenderer renderer(2);
  renderer.set_limits({3, 0.0, 0.0});
  const Snapshot done = wait_finished(renderer, renderer.submit(lit_scene(48, 32)));
  ASSERT_TRUE(done);
  EXPECT_EQ(done->stats.spp, 3u);
  const uint64_t generation = renderer.generation();
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(renderer.generation(), generation);
  EXPECT_EQ(renderer.latest(), done);
}

// Every call the editor makes, as fast as it can make them, while the worker renders
// (about 6,000 submits; the worker publishes over a thousand images meanwhile). Under a
// second in Release on 2 cores, so the sanitizer run (about 5x slower) keeps the default;
// INKRAY_STORM_EDITS (default 10000) scales it should it ever need cutting there.
TEST(ProgressiveRendererStorm, EndsInTheImageOfAFreshRenderer) {
  const char* env = std::getenv("INKRAY_STORM_EDITS");
  const int edits = env ? std::max(1, std::atoi(env)) : 10000;
  const size_t resident_before = resident_bytes();
  {
    ProgressiveRenderer storm(2);
    SceneDesc doc = lit_scene(48, 32);
    ViewportView view;
    std::mt19937 rng(20240611);
    const auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    storm.set_limits({2, 0.0, 0.0});
    storm.submit(doc);
    uint64_t newest = 0;
    for (int i = 0; i < edits; ++i) {
      const int kind = pick(10);
      switch (kind) {
        case 0:
          doc.materials[size_t(pick(2))].data =
              DiffuseDesc{Color(uniform(0, 1), uniform(0, 1), uniform(0, 1))};
          break;
        case 1:
          std::get<PointLightDesc>(doc.lights[0].data).intensity = uniform(1, 40);
          break;
        case 2:
          doc.objects[0].transform.translate = Vec3(uniform(-0.5f, 0.5f), uniform(-0.2f, 0.5f), 0.f);
          break;
        case 3:
          doc.camera.look_from = Point3(uniform(-2, 2), uniform(0.2f, 2), uniform(4, 6));
          break;
        case 4:
          doc.outlines.silhouette.color = Color(uniform(0, 1), uniform(0, 1), uniform(0, 1));
          break;
        case 5:
          doc.render.spp = 1 + pick(8);
          break;
        case 6:
          view.encoding.exposure = uniform(-2, 2);
          storm.set_view(view);
          break;
        case 7:
          storm.set_paused(pick(2) == 0);
          break;
        case 8:
          if (pick(3) == 0) {
            storm.set_region({});
          } else {
            const float x = uniform(0, 0.8f), y = uniform(0, 0.8f);
            storm.set_region({x, y, x + uniform(0.05f, 0.2f), y + uniform(0.05f, 0.2f)});
          }
          break;
        case 9:
          storm.set_limits({1 + pick(6), 0.0, 0.0});
          break;
      }
      if (kind <= 5) storm.submit(doc);  // the document edits
      if (Snapshot s = storm.latest()) {
        ASSERT_GE(s->revision, newest) << "an older revision came back at edit " << i;
        newest = s->revision;
      }
      // The odd pause lets the worker get into every state: mid-compile, mid-pass, idle.
      if (pick(16) == 0) std::this_thread::sleep_for(std::chrono::microseconds(pick(2000)));
    }

    const ViewportLimits limits{4, 0.0, 0.0};
    storm.set_paused(false);
    storm.set_region({});
    storm.set_limits(limits);
    storm.set_view(view);
    const Snapshot last = wait_finished(storm, storm.submit(doc));
    ASSERT_TRUE(last) << "the final document did not finish within 60 s";

    ProgressiveRenderer fresh(2);
    fresh.set_view(view);
    fresh.set_limits(limits);
    const Snapshot expected = wait_finished(fresh, fresh.submit(doc));
    ASSERT_TRUE(expected);
    EXPECT_EQ(last->stats.spp, 4u);
    EXPECT_EQ(expected->stats.spp, 4u);
    ASSERT_EQ(last->width, expected->width);
    ASSERT_EQ(last->height, expected->height);
    EXPECT_TRUE(last->rgba == expected->rgba) << "the storm's final image differs from a fresh render";
  }
#ifndef INKRAY_TEST_ASAN
  // AddressSanitizer holds freed memory in quarantine; LeakSanitizer checks leaks there.
  const size_t resident_after = resident_bytes();
  EXPECT_LE(resident_after, resident_before + (size_t(64) << 20))
      << "resident " << (resident_before >> 20) << " MiB before, " << (resident_after >> 20) << " MiB after";
#else
  (void)resident_before;
#endif
}

}  // namespace
}  // namespace inkray
