// Opening in the background: a read can be cancelled, a newer open replaces an older
// one, and a finished read is handed over once.
#include "ui/model/scene_loader.h"

#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

namespace inkray {
namespace {

using testing::ScratchFolder;
using testing::write_file;

SceneLoadResult wait_for(SceneLoader& loader) {
  for (;;) {
    if (auto result = loader.take()) return std::move(*result);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// About 20 MB: a second or more to read, so a cancel lands while reading.
std::string many_objects(int count) {
  std::string text = R"({"format": "inkray-scene", "version": 1, "materials": [{"name": "m"}], "objects": [)";
  for (int i = 0; i < count; ++i) {
    text += (i ? "," : "");
    text += R"({"name": "o)" + std::to_string(i) +
            R"(", "material": "m", "shape": {"type": "sphere", "center": [1, 2, 3], "radius": 0.5}})";
  }
  return text + "]}";
}

TEST(SceneLoader, ReadsInTheBackgroundAndHandsTheResultOverOnce) {
  ScratchFolder dir;
  write_file(dir / "a.json", R"({"format": "inkray-scene", "version": 1, "camera": {"vfov": 33}})");
  SceneLoader loader;
  EXPECT_FALSE(loader.take());
  loader.start(dir / "a.json");
  const SceneLoadResult r = wait_for(loader);
  ASSERT_TRUE(r);
  EXPECT_EQ(r.scene->camera.vfov, 33.f);
  EXPECT_FALSE(loader.busy());
  EXPECT_FALSE(loader.take());
}

TEST(SceneLoader, CancelStopsAHugeRead) {
  ScratchFolder dir;
  write_file(dir / "huge.json", many_objects(200000));
  SceneLoader loader;
  loader.start(dir / "huge.json");
  loader.cancel();
  const SceneLoadResult r = wait_for(loader);
  EXPECT_TRUE(r.cancelled);
  EXPECT_FALSE(r);
}

TEST(SceneLoader, ANewerOpenReplacesOneInFlight) {
  ScratchFolder dir;
  write_file(dir / "huge.json", many_objects(200000));
  write_file(dir / "small.json", R"({"format": "inkray-scene", "version": 1, "camera": {"vfov": 21}})");
  SceneLoader loader;
  loader.start(dir / "huge.json");
  loader.start(dir / "small.json");
  EXPECT_EQ(loader.file(), dir / "small.json");
  const SceneLoadResult r = wait_for(loader);
  ASSERT_TRUE(r);
  EXPECT_EQ(r.scene->camera.vfov, 21.f);
}

}  // namespace
}  // namespace inkray
