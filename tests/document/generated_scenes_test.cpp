// The scene generators docs/benchmarks.md measures with (scripts/make_many_objects.py,
// scripts/make_big_mesh.py) write scenes that load without a message, at sizes small
// enough for a test: a generator that drifts from the format fails here, not in a
// measurement.
#include "core/document/json_io.h"
#include "support/file_helpers.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace inkray {
namespace {

// Runs a generator from the source tree; false when it failed.
bool run(const std::string& command) {
  return std::system(("cd " INKRAY_SOURCE_DIR " && " + command + " > /dev/null").c_str()) == 0;
}

TEST(GeneratedScenes, ManyObjectsLoads) {
  testing::ScratchFolder dir;
  ASSERT_TRUE(
      run("python3 scripts/make_many_objects.py " + dir.path().string() + " --objects 300 --materials 8"));
  const SceneLoadResult loaded = load_scene(dir / "many_objects.json");
  ASSERT_TRUE(loaded) << (loaded.errors.empty() ? "" : loaded.errors.front());
  EXPECT_TRUE(loaded.warnings.empty());
  EXPECT_EQ(loaded.scene->objects.size(), 301u);  // the spheres and the ground
  EXPECT_EQ(loaded.scene->materials.size(), 9u);  // theirs and the ground's
  EXPECT_FALSE(run("python3 scripts/make_many_objects.py " + dir.path().string() + " --objects 0"));
}

TEST(GeneratedScenes, BigMeshLoads) {
  testing::ScratchFolder dir;
  ASSERT_TRUE(run("python3 scripts/make_big_mesh.py " + dir.path().string() + " --triangles 2000"));
  const SceneLoadResult loaded = load_scene(dir / "big_mesh.json");
  ASSERT_TRUE(loaded) << (loaded.errors.empty() ? "" : loaded.errors.front());
  EXPECT_TRUE(loaded.warnings.empty());
}

}  // namespace
}  // namespace inkray
