// The time limit of a final render also cuts a pass in flight: a closed white room
// at 1024 bounces makes one pass long, and --time must still be honoured.
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

// Every path runs all 1024 bounces: a pass takes far longer than the millisecond allowed.
TEST(BatchDeadline, TheTimeLimitCutsAPassInFlight) {
  const CompileResult c = compile_scene(testing::white_room_scene(48, 32));
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
  const CompileResult c = compile_scene(testing::white_room_scene(8, 6));
  ASSERT_TRUE(c.scene);
  RenderSession session(2);
  session.set_scene(c.scene);
  const std::vector<PassRecord> history = render_batch(session, {2, 0.0});
  EXPECT_EQ(history.size(), 2u);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) ASSERT_EQ(session.film().samples_at(x, y), 2u);
}

// Passes of a millisecond: the deadline usually falls between two of them, where the
// next pass's start would clear a cancel; the loop must still stop.
TEST(BatchDeadline, ManyShortPassesStopAtTheLimit) {
  const CompileResult c = compile_scene(testing::one_sphere_scene(4, 4));
  ASSERT_TRUE(c.scene);
  for (int run = 0; run < 5; ++run) {
    RenderSession session(2);
    session.set_scene(c.scene);
    const std::vector<PassRecord> history = render_batch(session, {1 << 20, 0.05});
    EXPECT_LT(history.size(), size_t(1) << 20);
  }
}

}  // namespace
}  // namespace inkray
