// The compiler checks an edit on the items it changed (docs/architecture.md, "Checks of
// an edit"): after a document compiled, every edit that breaks one item of a shipped
// scene is refused with exactly the errors a compile from scratch gives, and the
// document mended compiles again.
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "tests/support/breaking_edits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace inkray {
namespace {

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(IncrementalChecks, AnEditIsRefusedAsACompileFromScratchRefusesIt) {
  CompileOptions options;
  options.stand_in_for_broken_graphs = true;
  options.stand_in_for_missing_assets = true;  // as the viewport compiles
  int refused = 0, compared = 0;
  for (const auto& file : testing::shipped_scenes()) {
    SceneLoadResult loaded = load_scene(file);
    if (!loaded) continue;  // a scene that needs files elsewhere (it is read for editing in other tests)
    SceneDesc original = *loaded.scene;
    for (StrokeEmitterDesc& e : original.strokes) e.count = std::min(e.count, 200);  // the test's time
    SceneCompiler compiler;
    const CompileResult first = compiler.compile(original, options);
    if (!first.scene) continue;
    for (const testing::NamedEdit& edit : testing::breaking_edits(original)) {
      SCOPED_TRACE(file.filename().string() + ": " + edit.what);
      SceneDesc broken = original;
      edit.apply(broken);
      const CompileResult incremental = compiler.compile(broken, options);
      const CompileResult fresh = compile_scene(broken, options);
      EXPECT_EQ(bool(incremental.scene), bool(fresh.scene));
      EXPECT_EQ(sorted(incremental.errors), sorted(fresh.errors));
      refused += !fresh.scene;
      ++compared;
      EXPECT_TRUE(compiler.compile(original, options).scene) << "the mended document compiles again";
    }
  }
  EXPECT_GT(compared, 300);
  EXPECT_GT(refused, 100);
}

}  // namespace
}  // namespace inkray
