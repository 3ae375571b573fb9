// A pass cancelled part way resumes where it stopped: its finished tiles keep
// their sample and are not rendered again, so a render interrupted any number of
// times (the editor's edits, exposure drags) ends with exactly the film of one
// that never was.
#include "core/render/render_session.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace inkray {
namespace {

TEST(CancelledPass, ResumesWhereItStopped) {
  SceneDesc d = testing::white_room_scene(64, 48);
  d.render.max_depth = 64;
  const CompileResult c = compile_scene(d);
  ASSERT_TRUE(c.scene);

  RenderSession uninterrupted(2);
  uninterrupted.set_scene(c.scene);
  for (int pass = 0; pass < 3; ++pass) ASSERT_TRUE(uninterrupted.render_pass());

  RenderSession interrupted(2);
  interrupted.set_scene(c.scene);
  int cancelled = 0;
  while (interrupted.stats().passes < 3) {
    std::thread canceller([&] {
      std::this_thread::sleep_for(std::chrono::microseconds(300));
      interrupted.cancel();
    });
    cancelled += interrupted.render_pass() ? 0 : 1;
    canceller.join();
  }
  const RgbImage a = uninterrupted.film().resolve(), b = interrupted.film().resolve();
  EXPECT_EQ(a.pixels, b.pixels) << "after " << cancelled << " cancelled passes";
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) ASSERT_EQ(interrupted.film().samples_at(x, y), 3u);
}

// A cancel between passes (a time limit reached, a request the viewport's worker has
// not taken) stops the next pass before its first tile, and is spent there.
TEST(CancelledPass, ACancelBeforeAPassStopsThatPassAndEndsThere) {
  const CompileResult c = compile_scene(testing::white_room_scene(32, 24));
  ASSERT_TRUE(c.scene);
  RenderSession session(2);
  session.set_scene(c.scene);
  session.cancel();
  EXPECT_FALSE(session.render_pass());
  EXPECT_EQ(session.stats().passes, 0u);
  EXPECT_EQ(session.film().samples_at(0, 0), 0u);
  EXPECT_TRUE(session.render_pass());
  session.cancel();
  session.clear_cancel();  // withdrawn: the worker took the request it was for
  EXPECT_TRUE(session.render_pass());
  EXPECT_EQ(session.stats().passes, 2u);
}

}  // namespace
}  // namespace inkray
