// The time limit of a final render also cuts a pass in flight: a closed white room
// at 1024 bounces makes one pass long, and --time must still be honoured.
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

TEST(BatchDeadline, TheTimeLimitCutsAPassInFlightAfterTheFirst) {
  SceneDesc d = testing::small_scene(48, 32);
  d.render.max_depth = 1024;
  d.camera.look_from = Point3(0.f);
  d.camera.look_at = Point3(0.f, 0.f, -1.f);
  d.materials = {{"white", DiffuseDesc{Color(1.f)}, {}}};
  ObjectDesc room;
  room.name = "room";
  room.material = "white";
  room.shape = SphereDesc{Point3(0.f), 10.f};
  d.objects = {room};
  const CompileResult c = compile_scene(d);
  ASSERT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  RenderSession session(2);
  session.set_scene(c.scene);
  // Every path runs all 1024 bounces: a pass takes far longer than the millisecond left.
  const std::vector<PassRecord> history = render_batch(session, {1000, 1e-3});
  ASSERT_EQ(history.size(), 1u) << "the second pass ran to its end";
  EXPECT_EQ(session.stats().spp, 1u);
  // The first pass reached every pixel.
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) ASSERT_GE(session.film().samples_at(x, y), 1u) << x << "," << y;
}

}  // namespace
}  // namespace inkray
