// Edits of what the film's resolve reads (line colours and opacity, the painterly
// filter) re-composite the accumulated samples: the viewport keeps its sample
// count, and the image equals a render of the edited document from the start.
#include "core/render/progressive_renderer.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <thread>

namespace inkray {
namespace {

using Snapshot = std::shared_ptr<const ViewportSnapshot>;

Snapshot wait_until(ProgressiveRenderer& renderer, const std::function<bool(const ViewportSnapshot&)>& done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < give_up) {
    if (Snapshot s = renderer.latest(); s && done(*s)) return s;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return nullptr;
}

SceneDesc outlined_ball() {
  SceneDesc d = testing::one_sphere_scene(80, 60);
  d.lights.push_back({"lamp", PointLightDesc{Point3(2.f, 3.f, 4.f), Color(1.f), 40.f}});
  d.outlines.enabled = true;
  d.outlines.width = 3.f;
  d.outlines.silhouette.color = Color(0.f, 0.f, 1.f);
  return d;
}

// The finished image of a renderer given only this document.
Snapshot render_alone(const SceneDesc& d, int spp) {
  ProgressiveRenderer fresh(2);
  fresh.set_limits({spp, 0.0, 0.0});
  const uint64_t only = fresh.submit(d);
  return wait_until(fresh, [&](const auto& s) { return s.revision == only && s.finished; });
}

void expect_kept_samples(const SceneDesc& before, const SceneDesc& after, const std::string& what) {
  SCOPED_TRACE(what);
  ProgressiveRenderer renderer(2);
  renderer.set_limits({6, 0.0, 0.0});
  const uint64_t first = renderer.submit(before);
  const Snapshot done =
      wait_until(renderer, [&](const auto& s) { return s.revision == first && s.finished; });
  ASSERT_TRUE(done);
  ASSERT_EQ(done->stats.spp, 6u);
  const uint64_t second = renderer.submit(after);
  const Snapshot edited = wait_until(renderer, [&](const auto& s) { return s.revision == second; });
  ASSERT_TRUE(edited);
  EXPECT_EQ(edited->accumulation, done->accumulation) << "the edit restarted the film";
  EXPECT_EQ(edited->stats.spp, 6u) << "samples were lost";
  EXPECT_NE(edited->rgba, done->rgba) << "the edit did not show";

  // The same image as a render of the edited document from the start.
  const Snapshot reference = render_alone(after, 6);
  ASSERT_TRUE(reference);
  EXPECT_EQ(edited->rgba, reference->rgba);
}

TEST(ResolveEdits, LineColourKeepsTheSamples) {
  SceneDesc after = outlined_ball();
  after.outlines.silhouette.color = Color(1.f, 0.5f, 0.f);
  expect_kept_samples(outlined_ball(), after, "silhouette colour");
}

TEST(ResolveEdits, LineOpacityKeepsTheSamples) {
  SceneDesc after = outlined_ball();
  after.outlines.silhouette.opacity = 0.3f;
  expect_kept_samples(outlined_ball(), after, "silhouette opacity");
}

TEST(ResolveEdits, PainterlyFilterKeepsTheSamples) {
  SceneDesc after = outlined_ball();
  after.render.painterly = PainterlyFilter::kuwahara;
  after.render.painterly_radius = 64.f;  // pixels at 1080 lines: 3.6 here
  expect_kept_samples(outlined_ball(), after, "painterly filter");
}

TEST(ResolveEdits, AMaterialEditRestarts) {
  ProgressiveRenderer renderer(2);
  renderer.set_limits({4, 0.0, 0.0});
  SceneDesc d = outlined_ball();
  const uint64_t first = renderer.submit(d);
  ASSERT_TRUE(wait_until(renderer, [&](const auto& s) { return s.revision == first && s.finished; }));
  std::get<DiffuseDesc>(d.materials[0].data).albedo = Color(0.2f, 0.8f, 0.2f);
  const uint64_t second = renderer.submit(d);
  const Snapshot edited =
      wait_until(renderer, [&](const auto& s) { return s.revision == second && s.finished; });
  ASSERT_TRUE(edited);
  const uint64_t restarted = edited->accumulation;
  // The samples are all new: the image equals a render of the edited document alone.
  const Snapshot reference = render_alone(d, 4);
  ASSERT_TRUE(reference);
  EXPECT_EQ(edited->rgba, reference->rgba);
  EXPECT_NE(restarted, 0u);
}

}  // namespace
}  // namespace inkray
