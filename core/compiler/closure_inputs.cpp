#include "core/compiler/closure_inputs.h"

#include "core/document/graph_sockets.h"

#include <array>
#include <cstddef>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>

namespace inkray {
namespace {

struct Binding {
  std::string_view socket;
  ClosureSetter set = nullptr;
};

ClosureSetter find(std::span<const Binding> bindings, std::string_view socket) {
  for (const Binding& b : bindings)
    if (b.socket == socket) return b.set;
  return nullptr;
}

// The material a setter writes: the alternative its leaf's template holds.
template <class M>
M& as(Material& m) {
  return std::get<M>(m);
}
Texture constant(const Vec3& v) { return Texture{ConstantTexture{v}}; }

// A row of ToonDesc's table as a binding: rows into ToonParams that are sockets
// (numbers and colours) set the compiled material's copy of the same member.
template <std::size_t I>
constexpr Binding toon_row() {
  constexpr auto row = std::get<I>(ParamTable<ToonDesc>::rows);
  using Row = std::decay_t<decltype(row)>;
  using T = typename Row::value_type;
  if constexpr (std::is_same_v<typename Row::owner_type, ToonParams> &&
                (std::is_same_v<T, float> || std::is_same_v<T, Color>)) {
    return {row.param.name, [](Material& m, const Vec3& v) {
              constexpr auto member = std::get<I>(ParamTable<ToonDesc>::rows).member;
              ToonParams& params = as<ToonMaterial>(m);
              if constexpr (std::is_same_v<T, float>) {
                params.*member = v.x;
              } else {
                params.*member = v;
              }
            }};
  } else {
    return {};
  }
}

template <std::size_t... I>
constexpr auto toon_rows(std::index_sequence<I...>) {
  return std::array<Binding, sizeof...(I)>{toon_row<I>()...};
}

constexpr Binding kDiffuse[] = {
    {"albedo", [](Material& m, const Vec3& v) { as<DiffuseMaterial>(m).albedo = constant(v); }},
};
constexpr Binding kConductor[] = {
    {"color", [](Material& m, const Vec3& v) { as<ConductorMaterial>(m).color = constant(v); }},
    {"roughness", [](Material& m, const Vec3& v) { as<ConductorMaterial>(m).alpha = sqr(v.x); }},
};
constexpr Binding kDielectric[] = {
    {"ior", [](Material& m, const Vec3& v) { as<DielectricMaterial>(m).bsdf.eta = v.x; }},
    {"roughness", [](Material& m, const Vec3& v) { as<DielectricMaterial>(m).bsdf.alpha = sqr(v.x); }},
    {"tint", [](Material& m, const Vec3& v) { as<DielectricMaterial>(m).bsdf.tint = v; }},
};
constexpr Binding kEmissive[] = {
    {"color", [](Material& m, const Vec3& v) { as<EmissiveMaterial>(m).color = constant(v); }},
    {"strength", [](Material& m, const Vec3& v) { as<EmissiveMaterial>(m).strength = v.x; }},
};
constexpr Binding kUnlit[] = {
    {"color", [](Material& m, const Vec3& v) { as<UnlitMaterial>(m).color = constant(v); }},
};
constexpr Binding kTransparent[] = {
    {"tint", [](Material& m, const Vec3& v) { as<TransparentMaterial>(m).tint = v; }},
};
// The toon's lit colour is a texture in the material; its other inputs are settings.
constexpr Binding kToonColor[] = {
    {"color", [](Material& m, const Vec3& v) { as<ToonMaterial>(m).color = constant(v); }},
};
constexpr auto kToonSettings =
    toon_rows(std::make_index_sequence<std::tuple_size_v<decltype(ParamTable<ToonDesc>::rows)>>{});

struct ClosureKind {
  std::string_view type;
  std::span<const Binding> first, second;
};
constexpr ClosureKind kKinds[] = {
    {DiffuseDesc::type_name, kDiffuse, {}},
    {ConductorDesc::type_name, kConductor, {}},
    {DielectricDesc::type_name, kDielectric, {}},
    {EmissiveDesc::type_name, kEmissive, {}},
    {UnlitDesc::type_name, kUnlit, {}},
    {TransparentDesc::type_name, kTransparent, {}},
    {ToonDesc::type_name, kToonColor, kToonSettings},
};

}  // namespace

ClosureSetter closure_input_setter(std::string_view type, std::string_view socket) {
  for (const ClosureKind& kind : kKinds) {
    if (kind.type != type) continue;
    if (const ClosureSetter set = find(kind.first, socket)) return set;
    return find(kind.second, socket);
  }
  return nullptr;
}

}  // namespace inkray
