#include "ui/model/file_drop.h"

#include "core/document/param_text.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <type_traits>

namespace inkray {
namespace {

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Points the first colour input of a material's parameter list at the image.
struct FirstColorInput {
  std::string path;
  bool done = false;
  template <class T>
  void operator()(const Param&, T& value) {
    if constexpr (std::is_same_v<T, ColorInput>) {
      if (!done) value = ImageTextureDesc{path}, done = true;
    }
  }
};

bool set_material_texture(MaterialDesc& material, const std::string& path, std::string* why) {
  if (std::holds_alternative<GraphDesc>(material.data)) {
    *why = "material \"" + material.name + "\" is a node graph: add an Image node in the node editor";
    return false;
  }
  FirstColorInput setter{path};
  std::visit([&](auto& alternative) { visit_params(alternative, setter); }, material.data);
  if (!setter.done) *why = "material \"" + material.name + "\" has no colour input to take a texture";
  return setter.done;
}

}  // namespace

DropKind drop_kind(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  if (ext == ".json") return DropKind::scene;
  if (ext == ".obj") return DropKind::mesh;
  const auto images = file_extensions(FileType::image);  // what textures and brushes are read from
  if (std::find(images.begin(), images.end(), ext) != images.end()) return DropKind::image;
  return DropKind::unknown;
}

bool drop_image_on(SceneDesc& scene, const Selection& selection, const std::filesystem::path& image,
                   std::string* why) {
  std::string reason;
  const std::string path = path_in_scene(image, scene.base_dir);
  bool done = false;
  if (!is_valid(scene, selection)) {
    reason = "select a material, an object or a stroke emitter to drop an image on";
  } else if (selection.kind == ItemKind::material) {
    done = set_material_texture(scene.materials[size_t(selection.index)], path, &reason);
  } else if (selection.kind == ItemKind::object) {
    const std::string& name = scene.objects[size_t(selection.index)].material;
    const auto it = std::find_if(scene.materials.begin(), scene.materials.end(),
                                 [&](const MaterialDesc& m) { return m.name == name; });
    if (it == scene.materials.end()) {
      reason = "object \"" + scene.objects[size_t(selection.index)].name + "\" has no material";
    } else {
      done = set_material_texture(*it, path, &reason);
    }
  } else if (selection.kind == ItemKind::emitter) {
    StrokeEmitterDesc& emitter = scene.strokes[size_t(selection.index)];
    emitter.brush = BrushKind::image;
    emitter.brush_image = path;
    done = true;
  } else {
    reason = "a " + item_name(scene, selection) +
             " cannot take an image; select a material, an object or a stroke emitter";
  }
  if (!done && why) *why = image.string() + ": " + reason;
  return done;
}

}  // namespace inkray
