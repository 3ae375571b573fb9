// Every kind of compiled material against what it promises: its MaterialTraits
// flags and the values its example below states. The kinds are walked through
// the variant itself, so a new alternative is checked as soon as it exists (and
// does not compile here until it has an example).
#include "core/materials/material.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace inkray {
namespace {

// A material of kind T and what it must give at a hit whose vertex colour is
// si.color. No general definition: each alternative needs its own.
template <class T>
struct Example;

template <>
struct Example<DiffuseMaterial> {
  static Material make() { return DiffuseMaterial{ConstantTexture{Color(0.5f)}}; }
  static Color albedo(const SurfaceInteraction& si) { return si.color * 0.5f; }
  static std::optional<Bsdf> bsdf(const SurfaceInteraction& si) { return LambertBsdf{si.color * 0.5f}; }
};
template <>
struct Example<ConductorMaterial> {
  static Material make() {
    return ConductorMaterial{{0.5f}, ConstantTexture{Color(0.9f, 0.6f, 0.3f)}};
  }  // alpha 0.25
  static Color albedo(const SurfaceInteraction& si) { return si.color * Color(0.9f, 0.6f, 0.3f); }
  static std::optional<Bsdf> bsdf(const SurfaceInteraction& si) {
    return ConductorBsdf{si.color * Color(0.9f, 0.6f, 0.3f), 0.25f};
  }
};
template <>
struct Example<DielectricMaterial> {
  static Material make() { return DielectricMaterial{{1.33f, 0.5f, Color(0.8f, 0.9f, 1.f)}}; }  // alpha 0.25
  // Glass is not tinted by vertex colour.
  static Color albedo(const SurfaceInteraction&) { return Color(0.8f, 0.9f, 1.f); }
  static std::optional<Bsdf> bsdf(const SurfaceInteraction&) {
    return DielectricBsdf{1.33f, 0.25f, Color(0.8f, 0.9f, 1.f)};
  }
};
template <>
struct Example<EmissiveMaterial> {
  static Material make() { return EmissiveMaterial{{4.f, false}, ConstantTexture{Color(1.f, 0.5f, 0.25f)}}; }
  static Color albedo(const SurfaceInteraction&) { return Color(1.f, 0.5f, 0.25f); }
  static std::optional<Bsdf> bsdf(const SurfaceInteraction&) { return std::nullopt; }
  static Color emission(const SurfaceInteraction& si) { return 4.f * si.color * Color(1.f, 0.5f, 0.25f); }
};
template <>
struct Example<UnlitMaterial> {
  static Material make() { return UnlitMaterial{ConstantTexture{Color(0.2f, 0.4f, 0.6f)}}; }
  static Color albedo(const SurfaceInteraction&) { return Color(0.2f, 0.4f, 0.6f); }
  static std::optional<Bsdf> bsdf(const SurfaceInteraction&) { return std::nullopt; }
};
template <>
struct Example<TransparentMaterial> {
  static Material make() { return TransparentMaterial{{Color(0.7f, 0.8f, 0.9f)}}; }
  static Color albedo(const SurfaceInteraction&) { return Color(0.7f, 0.8f, 0.9f); }
  static std::optional<Bsdf> bsdf(const SurfaceInteraction&) {
    return TransparentBsdf{Color(0.7f, 0.8f, 0.9f)};
  }
};
template <>
struct Example<ToonMaterial> {
  static Material make() {
    ToonMaterial m;
    m.color = ConstantTexture{Color(0.3f, 0.6f, 0.9f)};
    return m;
  }
  static Color albedo(const SurfaceInteraction& si) { return si.color * Color(0.3f, 0.6f, 0.9f); }
  // Light bouncing off it sees a Lambertian of its lit colour.
  static std::optional<Bsdf> bsdf(const SurfaceInteraction& si) {
    return LambertBsdf{si.color * Color(0.3f, 0.6f, 0.9f)};
  }
};
template <>
struct Example<MixMaterial> {
  static Material make() { return MixMaterial{0, 1, ConstantTexture{Color(0.5f)}}; }
  // A mix is resolved before anything else is asked of it.
  static Color albedo(const SurfaceInteraction&) { return Color(0.f); }
  static std::optional<Bsdf> bsdf(const SurfaceInteraction&) { return std::nullopt; }
};

template <>
struct Example<GraphMaterial> {
  static Material make() { return GraphMaterial{std::make_shared<const ShaderProgram>()}; }
  // A graph is run before anything else is asked of it.
  static Color albedo(const SurfaceInteraction&) { return Color(0.f); }
  static std::optional<Bsdf> bsdf(const SurfaceInteraction&) { return std::nullopt; }
};

template <class T>
concept HasEmission = requires(const SurfaceInteraction& si) {
  Example<T>::emission(si);
};

bool same_bsdf(const LambertBsdf& a, const LambertBsdf& b) { return a.albedo == b.albedo; }
bool same_bsdf(const ConductorBsdf& a, const ConductorBsdf& b) { return a.f0 == b.f0 && a.alpha == b.alpha; }
bool same_bsdf(const DielectricBsdf& a, const DielectricBsdf& b) {
  return a.eta == b.eta && a.alpha == b.alpha && a.tint == b.tint;
}
bool same_bsdf(const TransparentBsdf& a, const TransparentBsdf& b) { return a.tint == b.tint; }
bool same_bsdf(const std::optional<Bsdf>& a, const std::optional<Bsdf>& b) {
  if (!a || !b) return !a && !b;
  if (a->index() != b->index()) return false;
  return std::visit([&]<class B>(const B& x) { return same_bsdf(x, std::get<B>(*b)); }, *a);
}

::testing::AssertionResult near(const Color& got, const Color& want) {
  if (glm::all(glm::lessThanEqual(glm::abs(got - want), Color(1e-6f)))) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got (" << got.r << ", " << got.g << ", " << got.b << "), want ("
                                       << want.r << ", " << want.g << ", " << want.b << ")";
}

template <size_t I>
void check_alternative() {
  using T = std::variant_alternative_t<I, Material>;
  constexpr MaterialFlags flags = MaterialTraits<T>::flags;
  SCOPED_TRACE("Material alternative " + std::to_string(I));
  const Material material = Example<T>::make();
  ASSERT_EQ(material.index(), I);

  // The runtime flags are the type's.
  const MaterialFlags got = material_flags(material);
  EXPECT_EQ(got.scatters, flags.scatters);
  EXPECT_EQ(got.emits, flags.emits);
  EXPECT_EQ(got.transmits, flags.transmits);
  EXPECT_EQ(got.resolves, flags.resolves);
  EXPECT_EQ(material_has_transmission(material), flags.transmits);
  // A mix or graph stands for others; what it is made of does the rest.
  if (flags.resolves) {
    EXPECT_FALSE(flags.scatters || flags.emits || flags.transmits);
  }
  // Light is either sent out or scattered here, never both.
  EXPECT_FALSE(flags.scatters && flags.emits);

  // With and without a vertex colour, which multiplies base colours.
  for (const Color vertex : {Color(1.f), Color(0.5f, 0.25f, 1.f)}) {
    SurfaceInteraction si;
    si.uv = Vec2(0.3f, 0.7f);
    si.color = vertex;

    const std::optional<Bsdf> bsdf = material_bsdf(material, si);
    EXPECT_EQ(bsdf.has_value(), flags.scatters);
    EXPECT_TRUE(same_bsdf(bsdf, Example<T>::bsdf(si)));
    EXPECT_TRUE(near(material_albedo(material, si), Example<T>::albedo(si)));

    EXPECT_EQ(material_is_emissive(material), flags.emits);
    const Color front = material_emission(material, si, 0.5f);
    const Color back = material_emission(material, si, -0.5f);
    EXPECT_TRUE(is_black(back));  // the example emitter is one-sided
    if constexpr (HasEmission<T>) {
      EXPECT_TRUE(flags.emits);
      EXPECT_TRUE(near(front, Example<T>::emission(si)));
      EXPECT_GT(luminance(material_average_emission(material)), 0.f);
    } else {
      EXPECT_FALSE(flags.emits) << "an emitting kind's example must state its emission";
      EXPECT_TRUE(is_black(front));
      EXPECT_TRUE(is_black(material_average_emission(material)));
    }
  }
}

template <size_t... I>
void check_alternatives(std::index_sequence<I...>) {
  (check_alternative<I>(), ...);
}

TEST(MaterialDispatch, EveryAlternativeKeepsItsPromises) {
  check_alternatives(std::make_index_sequence<std::variant_size_v<Material>>{});
}

// A two-sided emitter shows from behind; a black or unlit one is no light.
TEST(MaterialDispatch, EmissionSidesAndStrength) {
  const SurfaceInteraction si;
  const Material two_sided = EmissiveMaterial{{2.f, true}, ConstantTexture{Color(1.f)}};
  EXPECT_TRUE(near(material_emission(two_sided, si, -0.5f), Color(2.f)));
  EXPECT_TRUE(near(material_average_emission(two_sided), Color(2.f)));
  EXPECT_FALSE(material_is_emissive(EmissiveMaterial{{0.f, false}, ConstantTexture{Color(1.f)}}));
  EXPECT_FALSE(material_is_emissive(EmissiveMaterial{{5.f, false}, ConstantTexture{Color(0.f)}}));
}

// resolve_material reaches a kind that is not a mix through nested mixes, by the factor's luminance.
TEST(MaterialDispatch, ResolveReachesAKindThatIsNotAMix) {
  const std::vector<Material> materials = {
      DiffuseMaterial{ConstantTexture{Color(0.5f)}},                // 0
      EmissiveMaterial{{1.f, false}, ConstantTexture{Color(1.f)}},  // 1
      MixMaterial{0, 1, ConstantTexture{Color(0.25f)}},             // 2: b a quarter of the time
      MixMaterial{2, 0, ConstantTexture{Color(1.f)}},               // 3: always b
      MixMaterial{2, 0, ConstantTexture{Color(0.f)}},               // 4: always a, the mix 2
  };
  const SurfaceInteraction si;
  const ShadingPoint sp = shading_point(si, Vec3(0.f, 0.f, 1.f));
  Material scratch;
  const auto resolve = [&](const std::vector<Material>& list, uint32_t index, float u) -> uint32_t {
    const ResolvedMaterial r = resolve_material(list, index, sp, u, scratch);
    EXPECT_EQ(r.weight, 1.f);
    return r.material ? uint32_t(r.material - list.data()) : kNoMaterial;
  };
  EXPECT_EQ(resolve(materials, 0, 0.9f), 0u);
  EXPECT_EQ(resolve(materials, 2, 0.1f), 1u);
  EXPECT_EQ(resolve(materials, 2, 0.3f), 0u);
  EXPECT_EQ(resolve(materials, 3, 0.1f), 0u);
  EXPECT_EQ(resolve(materials, 4, 0.1f), 1u);
  EXPECT_EQ(resolve(materials, 4, 0.9f), 0u);
  for (float u = 0.f; u < 1.f; u += 0.0625f)
    EXPECT_FALSE(material_flags(materials[resolve(materials, 4, u)]).resolves);
  // A cycle (which compilation rejects) ends in no material rather than looping.
  const std::vector<Material> cycle = {MixMaterial{1, 1, ConstantTexture{Color(0.f)}},
                                       MixMaterial{0, 0, ConstantTexture{Color(0.f)}}};
  EXPECT_EQ(resolve(cycle, 0, 0.5f), kNoMaterial);
}

}  // namespace
}  // namespace inkray
