// Stroke colours from the material under each root.
#include "core/npr/strokes/stroke_color.h"

#include "core/base/parallel.h"
#include "core/image/image_io.h"
#include "core/math/color_space.h"
#include "core/math/hash.h"

namespace inkray {
namespace {

constexpr uint32_t kColorStream = 0x7f4a7c15u;

Color encode(const Color& c) { return {linear_to_srgb(c.r), linear_to_srgb(c.g), linear_to_srgb(c.b)}; }
Color decode(const Color& c) { return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)}; }

}  // namespace

Color root_color(std::span<const Material> materials, uint32_t material, const SurfacePoint& root,
                 float mix_u, const Transform& to_object) {
  SurfaceInteraction si;
  si.p = root.p;
  si.ng = root.ng;
  si.ns = root.n;
  si.uv = root.uv;
  si.color = root.color;
  si.prim = root.prim;
  // Strokes are painted seen head-on: the view is along the normal.
  ShadingPoint sp = shading_point(si, root.n);
  sp.material_id = material;
  sp.p_object = to_object.point(root.p);
  if (material < materials.size() && std::holds_alternative<GraphMaterial>(materials[material])) {
    if (auto c = material_overrides(materials, material, sp, mix_u).stroke_color) return *c;
  }
  Material scratch;
  const ResolvedMaterial resolved = resolve_material(materials, material, sp, mix_u, scratch);
  if (!resolved.material) return Color(0.f);
  return material_albedo(*resolved.material, si);
}

std::vector<Color> stroke_colors(std::span<const Material> materials, uint32_t material,
                                 std::span<const SurfacePoint> roots, const StrokeEmitterDesc& e,
                                 const Transform& to_object) {
  const uint32_t seed = hash_combine(uint32_t(e.seed), kColorStream);
  std::vector<Color> colors(roots.size());
  parallel_for_chunks(roots.size(), 8192, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const auto u = [&](uint32_t dim) { return u32_to_unit_float(hash_combine(seed, uint32_t(i), dim)); };
      const Color base = root_color(materials, material, roots[i], u(0), to_object);
      // Display-space values above 1 would be clamped by the HSV edit: keep the
      // colour's intensity out of it and put it back afterwards.
      const float scale = std::max(1.f, max_component(base));
      const Color jittered =
          jitter_hsv(encode(base / scale), e.hue_jitter * (2.f * u(1) - 1.f),
                     e.saturation_jitter * (2.f * u(2) - 1.f), e.value_jitter * (2.f * u(3) - 1.f));
      colors[i] = decode(jittered) * scale;
    }
  });
  return colors;
}

}  // namespace inkray
