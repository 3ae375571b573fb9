// The time limit of a final render also cuts a pass in flight: a closed white room
// at 1024 bounces makes one pass long, and --time must still be honoured.
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

SceneDesc white_room(int width, int height) {
  SceneDesc d = testing::small_scene(width, height);
  d.render.max_depth = 1024;
  d.camera.look_from = Point3(0.f);
  d.camera.look_at = Point3(0.f, 0.f, -1.f);
  d.materials = {{"white", DiffuseDesc{Color(1.f)}, {}}};
  ObjectDesc room;
  room.name = "room";
  room.material = "white";
  room.shape = SphereDesc{Point3(0.f), 10.f};
  d.objects = {room};
  return d;
}

// Every path runs all 1024 bounces: a pass takes far longer than the millisecond allowed.
TEST(BatchDeadline, TheTimeLimitCutsAPassInFlight) {
  const CompileResult c = compile_scene(white_room(48, 32));
  ASSERT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  RenderSession session(2);
  session.set_scene(c.scene);
  const std::vector<PassRecord> history = render_batch(session, {1000, 1e-3});
  EXPECT_TRUE(history.empty()) << "a pass ran to its end";
  EXPECT_EQ(session.stats().spp, 0u);
  bool some_pixel_left = false;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) some_pixel_left |= session.film().samples_at(x, y) == 0;
  EXPECT_TRUE(some_pixel_left);
}

// Without a limit the same scene renders its passes in full.
TEST(BatchDeadline, NoLimitRendersEveryPass) {
  const CompileResult c = compile_scene(white_room(8, 6));
  ASSERT_TRUE(c.scene);
  RenderSession session(2);
  session.set_scene(c.scene);
  const std::vector<PassRecord> history = render_batch(session, {2, 0.0});
  EXPECT_EQ(history.size(), 2u);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) ASSERT_EQ(session.film().samples_at(x, y), 2u);
}

}  // namespace
}  // namespace inkray
