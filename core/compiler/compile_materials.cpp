// Material compilation. Mixes refer to other materials by name, possibly to ones
// later in the list, so they are compiled last, in dependency order, and a cycle
// is an error rather than a loop.
#include "core/compiler/compile_materials.h"

#include "core/compiler/closure_inputs.h"
#include "core/compiler/compile_graph.h"

#include <array>
#include <deque>
#include <map>

namespace inkray {
namespace {

// Images by file name relative to the scene's folder, read through the compiler's
// cache: a material edit decodes nothing that was decoded before.
class ImageCache {
 public:
  ImageCache(std::filesystem::path base, AssetCache& assets) : base_(std::move(base)), assets_(assets) {}
  std::shared_ptr<const RgbImage> get(const ImageTextureDesc& d, std::string* error) {
    return assets_.image(base_ / d.path, d.srgb, error);
  }

 private:
  std::filesystem::path base_;
  AssetCache& assets_;
};

std::optional<Texture> compile_color(const ColorInput& input, ImageCache& images, std::string* error) {
  if (const auto* c = std::get_if<Color>(&input)) return ConstantTexture{*c};
  if (const auto* ch = std::get_if<CheckerTextureDesc>(&input))
    return CheckerTexture{ch->even, ch->odd, ch->scale};
  const auto& img = std::get<ImageTextureDesc>(input);
  auto image = images.get(img, error);
  if (!image) return std::nullopt;
  glm::dvec3 sum(0.0);
  for (const Color& c : image->pixels) sum += glm::dvec3(c);
  const Color average = image->pixels.empty() ? Color(0.f) : Color(sum / double(image->pixels.size()));
  return ImageTexture{std::move(image), img.scale, average};
}

// A plain material: its settings block copied whole, its colour inputs compiled to
// textures (CompiledMaterial in closure_inputs.h). A mix's sides are set later.
template <class D>
std::optional<Material> compile_plain(const D& d, ImageCache& images, std::string* error) {
  using Compiled = CompiledMaterial<D>;
  typename Compiled::type m;
  if constexpr (!std::is_void_v<typename Compiled::Params>)
    static_cast<typename Compiled::Params&>(m) = d;  // the settings, whole
  for (const auto& slot : Compiled::textures) {
    auto texture = compile_color(d.*slot.input, images, error);
    if (!texture) return std::nullopt;
    m.*slot.texture = std::move(*texture);
  }
  if constexpr (std::is_same_v<D, ToonDesc>) {
    if (!d.ramp.empty()) m.ramp = std::make_shared<const std::vector<Color>>(d.ramp);
    if (!d.ramp_image.empty()) {
      // A ramp holds colours, so 8-bit files are sRGB like colour textures.
      m.ramp_image = images.get(ImageTextureDesc{d.ramp_image, Color(1.f), true}, error);
      if (!m.ramp_image) return std::nullopt;
    }
  }
  return m;
}

// Everything but the indices of a mix; those are known once all materials are.
std::optional<Material> compile_material(const MaterialDesc& desc, ImageCache& images, AssetCache& assets,
                                         const std::filesystem::path& base_dir, std::string* error) {
  return std::visit(
      [&]<class T>(const T& m) -> std::optional<Material> {
        if constexpr (std::is_same_v<T, GraphDesc>) {
          std::vector<std::string> errors;
          auto program = compile_graph(m, base_dir, assets, errors);
          if (!program) {
            *error = errors.empty() ? "the graph did not compile" : errors.front();
            for (size_t k = 1; k < errors.size(); ++k) *error += "\n" + errors[k];  // one message each
            return std::nullopt;
          }
          return GraphMaterial{std::move(program)};
        } else {
          return compile_plain(m, images, error);
        }
      },
      desc.data);
}

// Points each compiled mix at its sides' document indices, in dependency order
// (Kahn's algorithm, no recursion): a mix whose sides are missing or failed
// fails, and mixes left over are on, or behind, a cycle.
template <class Fail>
void resolve_mixes(const SharedList<MaterialDesc>& list, std::vector<std::optional<Material>>& compiled,
                   Fail&& fail) {
  std::map<std::string, size_t> by_name;
  for (size_t i = 0; i < list.size(); ++i)
    by_name[list[i].name] = i;  // the last of a duplicate, like objects
  std::vector<size_t> pending(list.size(), 0);
  std::vector<std::vector<size_t>> users(list.size());
  std::vector<std::array<size_t, 2>> sides(list.size());
  std::deque<size_t> ready;
  for (size_t i = 0; i < list.size(); ++i) {
    const auto* d = std::get_if<MixDesc>(&list[i].data);
    if (!d) continue;
    const auto a = by_name.find(d->a), b = by_name.find(d->b);
    if (compiled[i] && (a == by_name.end() || b == by_name.end()))
      fail(i, "no material named \"" + (a == by_name.end() ? d->a : d->b) + "\"");
    if (!compiled[i]) {  // failed already: settled, so mixes that use it are not mistaken for a cycle
      ready.push_back(i);
      continue;
    }
    sides[i] = {a->second, b->second};
    for (size_t side : sides[i]) {
      if (!std::holds_alternative<MixDesc>(list[side].data)) continue;
      ++pending[i];
      users[side].push_back(i);
    }
    if (pending[i] == 0) ready.push_back(i);
  }
  std::vector<bool> done(list.size(), false);
  while (!ready.empty()) {
    const size_t i = ready.front();
    ready.pop_front();
    done[i] = true;
    const auto [a, b] = sides[i];
    if (compiled[i] && (!compiled[a] || !compiled[b])) {
      fail(i, "refers to material \"" + list[compiled[a] ? b : a].name + "\", which failed");
    } else if (compiled[i]) {
      auto& mix = std::get<MixMaterial>(*compiled[i]);
      mix.a = uint32_t(a);
      mix.b = uint32_t(b);
      const auto side_uses_light = [&](size_t s) {
        if (const auto* g = std::get_if<GraphMaterial>(&*compiled[s])) return g->program->uses_light;
        if (const auto* m = std::get_if<MixMaterial>(&*compiled[s])) return m->uses_light;
        return false;
      };
      mix.uses_light = side_uses_light(a) || side_uses_light(b);
    }
    for (size_t u : users[i])
      if (--pending[u] == 0) ready.push_back(u);
  }
  for (size_t i = 0; i < list.size(); ++i) {
    if (std::holds_alternative<MixDesc>(list[i].data) && compiled[i] && !done[i])
      fail(i, "mix is part of, or refers to, a cycle of mixes");
  }
}

// Sets every colour input to a constant: what a closure template is compiled from.
struct ClearTextures {
  template <class F>
  void operator()(const Param&, F& field) {
    if constexpr (std::is_same_v<F, ColorInput>) field = Color(0.f);
  }
};

}  // namespace

Material stand_in_material(float squares) {
  return UnlitMaterial{CheckerTexture{kStandInEven, kStandInOdd, squares}};
}

std::optional<Material> compile_closure_template(const MaterialVariant& data,
                                                 const std::filesystem::path& base_dir, AssetCache& assets,
                                                 std::string* error) {
  ImageCache images(base_dir, assets);
  MaterialDesc desc;
  desc.data = data;
  // Colour inputs are the graph's registers: the template keeps only the settings.
  std::visit(
      [](auto& m) {
        if constexpr (ParamGroup<std::decay_t<decltype(m)>>) {
          ClearTextures clear;
          visit_params(m, clear);
        }
      },
      desc.data);
  return compile_material(desc, images, assets, base_dir, error);
}

size_t compile_materials(const SceneDesc& desc, World& world, std::vector<std::string>& errors,
                         AssetCache& assets, std::vector<std::vector<std::string>>& keys,
                         const LastMaterials& last, std::vector<std::string>* broken_graphs) {
  const SharedList<MaterialDesc>& list = desc.materials;
  ImageCache images(desc.base_dir, assets);
  std::vector<std::optional<Material>> compiled(list.size());
  auto fail = [&](size_t i, const std::string& error) {
    const bool stand_in = broken_graphs && std::holds_alternative<GraphDesc>(list[i].data);
    size_t start = 0;
    while (start <= error.size()) {
      const size_t end = std::min(error.find('\n', start), error.size());
      const std::string line = "materials[" + std::to_string(i) + "] \"" + list[i].name +
                               "\": " + error.substr(start, end - start);
      (stand_in ? *broken_graphs : errors).push_back(line);
      start = end + 1;
    }
    if (stand_in) {
      compiled[i] = stand_in_material(40.f);
    } else {
      compiled[i].reset();
    }
  };
  // Mixes refer to materials by name, and the table by index: an entry can be kept
  // while every name stays where it was.
  bool same_names = last.desc && last.table && last.keys && last.desc->size() == list.size() &&
                    last.table->size() == list.size() && last.keys->size() == list.size();
  for (size_t i = 0; same_names && i < list.size(); ++i) same_names = (*last.desc)[i].name == list[i].name;
  size_t built = 0;
  std::vector<std::vector<std::string>> used(list.size());
  for (size_t i = 0; i < list.size(); ++i) {
    if (same_names && (*last.desc)[i] == list[i]) {
      compiled[i] = (*last.table)[i];
      used[i] = (*last.keys)[i];
      assets.touch(used[i]);
      continue;
    }
    std::string error;
    assets.record_keys(&used[i]);
    compiled[i] = compile_material(list[i], images, assets, desc.base_dir, &error);
    assets.record_keys(nullptr);
    ++built;
    if (!compiled[i]) fail(i, error);
  }
  keys = std::move(used);
  resolve_mixes(list, compiled, fail);

  // Document order, failed materials left out; mixes' document indices remapped.
  std::vector<uint32_t> remap(list.size(), kNoMaterial);
  for (size_t i = 0; i < list.size(); ++i) {
    if (!compiled[i]) continue;
    remap[i] = uint32_t(world.materials.size());
    world.materials.push_back(std::move(*compiled[i]));
    world.material_names.push_back(list[i].name);
  }
  for (Material& m : world.materials) {
    if (auto* mix = std::get_if<MixMaterial>(&m)) {
      mix->a = remap[mix->a];
      mix->b = remap[mix->b];
    }
  }
  return built;
}

}  // namespace inkray
