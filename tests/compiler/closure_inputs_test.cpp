// Every valued input of a closure node has a place in its compiled material, found by
// the socket's name (core/compiler/closure_inputs.h), and the toon closure's settings
// land in the member of ToonParams their table row names.
#include "core/compiler/closure_inputs.h"
#include "core/document/desc.h"
#include "core/document/graph_desc.h"
#include "core/document/graph_nodes.h"
#include "core/document/tagged_variant.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <type_traits>

namespace inkray {
namespace {

template <class T>
constexpr bool kIsClosure = std::is_constructible_v<MaterialVariant, T>;  // a plain material's description

TEST(ClosureInputs, EveryValuedSocketOfEveryClosureHasASetter) {
  size_t sockets = 0;
  for_each_alternative<NodeVariant>([&]<class T>(std::type_identity<T>) {
    if constexpr (kIsClosure<T>) {
      for (const SocketInfo& s : node_inputs_of<T>()) {
        if (!s.has_value) continue;
        ++sockets;
        EXPECT_NE(closure_input_setter(T::type_name, s.name), nullptr) << T::type_name << "." << s.name;
      }
      EXPECT_EQ(closure_input_setter(T::type_name, "no_such_input"), nullptr) << T::type_name;
    }
  });
  EXPECT_GE(sockets, 20u);  // the closures' inputs were found at all
}

// Each toon input that is a setting writes its own member of the block the material
// shares with the document, and no other: the material equals a default one with just
// that member changed.
TEST(ClosureInputs, ToonSettingsLandInTheirOwnMember) {
  size_t checked = 0;
  std::apply(
      [&](const auto&... row) {
        const auto one = [&](const auto& r) {
          using Row = std::decay_t<decltype(r)>;
          using V = typename Row::value_type;
          if constexpr (std::is_same_v<typename Row::owner_type, ToonParams> &&
                        (std::is_same_v<V, float> || std::is_same_v<V, Color>)) {
            const ClosureSetter set = closure_input_setter(ToonDesc::type_name, r.param.name);
            ASSERT_NE(set, nullptr) << r.param.name;
            Material m = ToonMaterial{};
            set(m, Vec3(0.375f, 0.5f, 0.625f));
            ToonParams expected;
            if constexpr (std::is_same_v<V, float>) {
              expected.*(r.member) = 0.375f;
            } else {
              expected.*(r.member) = Color(0.375f, 0.5f, 0.625f);
            }
            EXPECT_TRUE(static_cast<const ToonParams&>(std::get<ToonMaterial>(m)) == expected)
                << r.param.name;
            ++checked;
          }
        };
        (one(row), ...);
      },
      ParamTable<ToonDesc>::rows);
  EXPECT_EQ(checked, 12u);  // every toon socket but the lit colour, which is a texture
}

}  // namespace
}  // namespace inkray
