// Every material of every example scene has a swatch that compiles and shows the
// material: the sphere's pixels differ from the floor's, and nothing is NaN.
#include "core/render/material_preview.h"

#include "core/document/json_io.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace inkray {
namespace {

TEST(MaterialPreview, EveryExampleMaterialHasASwatch) {
  int swatches = 0;
  for (const auto& entry : std::filesystem::directory_iterator(INKRAY_SOURCE_DIR "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    const SceneLoadResult loaded = load_scene(entry.path());
    ASSERT_TRUE(loaded.scene) << entry.path();
    for (const MaterialDesc& m : loaded.scene->materials) {
      SCOPED_TRACE(entry.path().filename().string() + ": " + m.name);
      const SceneDesc swatch = material_preview_scene(*loaded.scene, m.name, 24, 2);
      const RgbImage img = testing::render_scene(swatch, 2, 1);
      ASSERT_EQ(img.pixels.size(), 24u * 24u);
      for (const Color& c : img.pixels)
        ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
      ++swatches;
    }
  }
  EXPECT_GT(swatches, 30);
}

TEST(MaterialPreview, AMixBringsItsSides) {
  SceneDesc doc;
  doc.materials = {{"a", DiffuseDesc{Color(1.f, 0.f, 0.f)}, {}},
                   {"unused", DiffuseDesc{}, {}},
                   {"b", UnlitDesc{Color(0.f, 0.f, 1.f)}, {}},
                   {"blend", MixDesc{"a", "b", Color(0.5f)}, {}}};
  const SceneDesc swatch = material_preview_scene(doc, "blend");
  std::vector<std::string> names;
  for (const MaterialDesc& m : swatch.materials) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"a", "b", "blend", "preview floor"}));
  EXPECT_TRUE(compile_scene(swatch).scene);
}

}  // namespace
}  // namespace inkray
