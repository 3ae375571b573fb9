#include "core/scene/compile_materials.h"

#include "core/image/image_io.h"

#include <map>

namespace inkray {
namespace {

// Loads each image file once per compile, however many materials use it.
class ImageCache {
 public:
  explicit ImageCache(std::filesystem::path base) : base_(std::move(base)) {}
  std::shared_ptr<const RgbImage> get(const ImageTextureDesc& d, std::string* error) {
    const std::filesystem::path file = base_ / d.path;
    const std::string key = file.string() + (d.srgb ? "#srgb" : "#linear");
    if (auto it = images_.find(key); it != images_.end()) return it->second;
    RgbImage image;
    if (!read_image(file, d.srgb, &image, error)) return nullptr;
    return images_[key] = std::make_shared<const RgbImage>(std::move(image));
  }

 private:
  std::filesystem::path base_;
  std::map<std::string, std::shared_ptr<const RgbImage>> images_;
};

std::optional<Texture> compile_color(const ColorInput& input, ImageCache& images, std::string* error) {
  if (const auto* c = std::get_if<Color>(&input)) return ConstantTexture{*c};
  if (const auto* ch = std::get_if<CheckerTextureDesc>(&input)) return CheckerTexture{ch->even, ch->odd, ch->scale};
  const auto& img = std::get<ImageTextureDesc>(input);
  auto image = images.get(img, error);
  if (!image) return std::nullopt;
  glm::dvec3 sum(0.0);
  for (const Color& c : image->pixels) sum += glm::dvec3(c);
  const Color average = image->pixels.empty() ? Color(0.f) : Color(sum / double(image->pixels.size()));
  return ImageTexture{std::move(image), img.scale, average};
}

std::optional<Material> compile_material(const MaterialDesc& desc, ImageCache& images, std::string* error) {
  auto tex = [&](const ColorInput& c) { return compile_color(c, images, error); };
  return std::visit(
      [&](const auto& m) -> std::optional<Material> {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, DiffuseDesc>) {
          auto t = tex(m.albedo);
          return t ? std::optional<Material>(DiffuseMaterial{*t}) : std::nullopt;
        } else if constexpr (std::is_same_v<T, ConductorDesc>) {
          auto t = tex(m.color);
          return t ? std::optional<Material>(ConductorMaterial{*t, m.roughness * m.roughness}) : std::nullopt;
        } else if constexpr (std::is_same_v<T, DielectricDesc>) {
          return DielectricMaterial{DielectricBsdf{m.ior, m.roughness * m.roughness, m.tint}};
        } else if constexpr (std::is_same_v<T, EmissiveDesc>) {
          auto t = tex(m.color);
          return t ? std::optional<Material>(EmissiveMaterial{*t, m.strength, m.two_sided}) : std::nullopt;
        } else if constexpr (std::is_same_v<T, UnlitDesc>) {
          auto t = tex(m.color);
          return t ? std::optional<Material>(UnlitMaterial{*t}) : std::nullopt;
        } else if constexpr (std::is_same_v<T, TransparentDesc>) {
          return TransparentMaterial{m.tint};
        } else {
          *error = "material type \"" + std::string(T::type_name) + "\" is not supported by this build yet";
          return std::nullopt;
        }
      },
      desc.data);
}

}  // namespace

void compile_materials(const SceneDesc& desc, RenderScene& scene, std::vector<std::string>& errors) {
  ImageCache images(desc.base_dir);
  for (size_t i = 0; i < desc.materials.size(); ++i) {
    std::string error;
    auto m = compile_material(desc.materials[i], images, &error);
    if (!m) {
      errors.push_back("materials[" + std::to_string(i) + "] \"" + desc.materials[i].name + "\": " + error);
      continue;
    }
    scene.materials.push_back(std::move(*m));
    scene.material_names.push_back(desc.materials[i].name);
  }
}

}  // namespace inkray
