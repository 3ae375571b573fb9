// Edits that keep every name of a document and each break one check of one item (or of
// the whole document), over the shipped scenes: what the checks of an edit
// (docs/architecture.md, "Checks of an edit") must find as checking everything would.
#pragma once

#include "core/document/desc.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace inkray::testing {

// scenes/ and tests/data/scenes/valid, in name order.
inline std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> files;
  for (const std::filesystem::path& dir :
       {std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes",
        std::filesystem::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "scenes" / "valid"})
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

struct NamedEdit {
  std::string what;
  std::function<void(SceneDesc&)> apply;
};

// Edits that keep every name and each break one check of one item (or of the whole
// document), for the first few items of each list.
inline std::vector<NamedEdit> breaking_edits(const SceneDesc& scene) {
  std::vector<NamedEdit> edits;
  const size_t most = 12;
  for (size_t i = 0; i < std::min(scene.objects.size(), most); ++i) {
    edits.push_back({"objects[" + std::to_string(i) + "].material dangling",
                     [i](SceneDesc& s) { s.objects[i].material = "no such material"; }});
    edits.push_back({"objects[" + std::to_string(i) + "].material empty",
                     [i](SceneDesc& s) { s.objects[i].material.clear(); }});
    edits.push_back({"objects[" + std::to_string(i) + "] a missing mesh",
                     [i](SceneDesc& s) { s.objects[i].shape = MeshDesc{"no/such/mesh.obj"}; }});
    edits.push_back({"objects[" + std::to_string(i) + "] moved",
                     [i](SceneDesc& s) { s.objects[i].transform.translate += Vec3(0.5f, 0.f, 0.f); }});
  }
  for (size_t i = 0; i < std::min(scene.materials.size(), most); ++i) {
    edits.push_back({"materials[" + std::to_string(i) + "] a mix of itself", [i](SceneDesc& s) {
                       s.materials[i].data = MixDesc{s.materials[i].name, s.materials[i].name};
                     }});
    edits.push_back({"materials[" + std::to_string(i) + "] a mix of nothing", [i](SceneDesc& s) {
                       s.materials[i].data = MixDesc{"", "nothing"};
                     }});
    edits.push_back({"materials[" + std::to_string(i) + "] a missing texture", [i](SceneDesc& s) {
                       s.materials[i].data = DiffuseDesc{ImageTextureDesc{"no/such/image.png"}};
                     }});
  }
  for (size_t i = 0; i < std::min(scene.lights.size(), most); ++i) {
    edits.push_back({"lights[" + std::to_string(i) + "] a spot at its target", [i](SceneDesc& s) {
                       SpotLightDesc spot;
                       spot.target = spot.position;
                       s.lights[i].data = spot;
                     }});
  }
  for (size_t i = 0; i < std::min(scene.strokes.size(), most); ++i) {
    edits.push_back({"strokes[" + std::to_string(i) + "] on nothing",
                     [i](SceneDesc& s) { s.strokes[i].object = "nobody"; }});
    edits.push_back({"strokes[" + std::to_string(i) + "] widths crossed",
                     [i](SceneDesc& s) { s.strokes[i].width_min = s.strokes[i].width_max + 1.f; }});
    edits.push_back({"strokes[" + std::to_string(i) + "] an image brush with no image", [i](SceneDesc& s) {
                       s.strokes[i].brush = BrushKind::image;
                       s.strokes[i].brush_image.clear();
                     }});
  }
  edits.push_back({"camera looking at its eye", [](SceneDesc& s) { s.camera.look_at = s.camera.look_from; }});
  edits.push_back({"frames reversed", [](SceneDesc& s) { s.render.frame_end = s.render.frame_start - 1; }});
  return edits;
}

}  // namespace inkray::testing
