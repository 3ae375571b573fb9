#include "core/compiler/closure_inputs.h"

#include "core/document/desc.h"
#include "core/document/graph_sockets.h"
#include "core/document/tagged_variant.h"

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

namespace inkray {
namespace {

struct Binding {
  std::string_view socket;
  ClosureSetter set = nullptr;
};

template <class D>
constexpr auto& kRows = ParamTable<D>::rows;

// Which of D's texture slots compiles the colour input `member`; past the end when none.
template <class D, class Member>
constexpr size_t texture_slot(Member member) {
  constexpr auto& slots = CompiledMaterial<D>::textures;
  for (size_t k = 0; k < slots.size(); ++k)
    if (slots[k].input == member) return k;
  return slots.size();
}

// Row I of D's table as a binding: a colour input sets its texture to the constant, a
// number or colour the compiled material's copy of the block member the row names.
// Rows that are no socket (toggles, choices, integers, ramps) bind nothing.
template <class D, std::size_t I>
constexpr Binding row_binding() {
  using Row = std::decay_t<decltype(std::get<I>(kRows<D>))>;
  using T = typename Row::value_type;
  using M = typename CompiledMaterial<D>::type;
  constexpr Param param = std::get<I>(kRows<D>).param;
  if constexpr (!socket_type_of(param.kind)) {
    return {};
  } else if constexpr (std::is_same_v<T, ColorInput>) {
    constexpr size_t slot = texture_slot<D>(std::get<I>(kRows<D>).member);
    static_assert(slot < CompiledMaterial<D>::textures.size(), "a colour input compiles to no texture");
    return {param.name, [](Material& m, const Vec3& v) {
              std::get<M>(m).*(CompiledMaterial<D>::textures[slot].texture) = Texture{ConstantTexture{v}};
            }};
  } else {
    using Block = typename Row::owner_type;
    static_assert(std::is_base_of_v<Block, M>, "a valued setting lies outside the block its material shares");
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, Color>);
    return {param.name, [](Material& m, const Vec3& v) {
              Block& block = std::get<M>(m);
              if constexpr (std::is_same_v<T, float>) {
                block.*(std::get<I>(kRows<D>).member) = v.x;
              } else {
                block.*(std::get<I>(kRows<D>).member) = v;
              }
            }};
  }
}

template <class D, std::size_t... I>
constexpr auto row_bindings(std::index_sequence<I...>) {
  return std::array<Binding, sizeof...(I)>{row_binding<D, I>()...};
}
template <class D>
constexpr auto kBindings =
    row_bindings<D>(std::make_index_sequence<std::tuple_size_v<std::decay_t<decltype(kRows<D>)>>>{});

// A plain material's description that is also a node of material graphs.
template <class D>
concept IsClosureNode = requires {
  D::outputs;
};

}  // namespace

ClosureSetter closure_input_setter(std::string_view type, std::string_view socket) {
  ClosureSetter found = nullptr;
  for_each_alternative<MaterialVariant>([&]<class D>(std::type_identity<D>) {
    if constexpr (IsClosureNode<D>) {
      if (D::type_name != type) return;
      for (const Binding& b : kBindings<D>)
        if (b.set && b.socket == socket) found = b.set;
    }
  });
  return found;
}

}  // namespace inkray
