// Every valued input of a closure node has a place in its compiled material, found by
// the socket's name (core/compiler/closure_inputs.h), and it is the place compiling a
// plain material puts the same parameter: the member of the block the material shares
// with the document, or the texture its colour input compiles to.
#include "core/compiler/closure_inputs.h"
#include "core/compiler/compile_materials.h"
#include "core/document/desc.h"
#include "core/document/graph_desc.h"
#include "core/document/graph_nodes.h"
#include "core/document/tagged_variant.h"
#include "tests/compiler/graph_edit_ops.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

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

// What compiling `desc` as a scene's only material makes of it, colour inputs included.
template <class D>
Material compiled(const D& desc) {
  SceneDesc scene;
  scene.materials.push_back({"m", desc, {}});
  World out;
  std::vector<std::string> errors;
  AssetCache assets;
  std::vector<std::vector<std::string>> keys;
  compile_materials(scene, out, errors, assets, keys);
  EXPECT_TRUE(errors.empty()) << D::type_name;
  return out.materials.empty() ? Material{} : out.materials[0];
}

// Sets the row's socket on the default material and checks the result is the material
// compiled from a description with only that parameter changed.
template <class D, class Row>
void check_row(const Row& r, size_t& checked) {
  using V = typename Row::value_type;
  if constexpr (!std::is_same_v<V, float> && !std::is_same_v<V, Color> && !std::is_same_v<V, ColorInput>) {
    EXPECT_FALSE(socket_type_of(r.param.kind)) << D::type_name << "." << r.param.name;
  } else {
    if (!socket_type_of(r.param.kind)) return;
    const ClosureSetter set = closure_input_setter(D::type_name, r.param.name);
    ASSERT_NE(set, nullptr) << D::type_name << "." << r.param.name;
    // Inside the parameter's hard range (materialise keeps it there) and unlike any default.
    const float lo = float(r.param.min), hi = float(std::min(r.param.max, r.param.min + 1.0));
    const Vec3 value = lo + (hi - lo) * Vec3(0.375f, 0.5f, 0.625f);
    D changed;
    if constexpr (std::is_same_v<V, float>) {
      changed.*(r.member) = value.x;
    } else {
      changed.*(r.member) = Color(value);
    }
    Material m = compiled(D{});
    set(m, value);
    const std::vector<float> got = graph_ops::material_numbers(m);
    EXPECT_EQ(got, graph_ops::material_numbers(compiled(changed))) << D::type_name << "." << r.param.name;
    EXPECT_NE(got, graph_ops::material_numbers(compiled(D{})))
        << D::type_name << "." << r.param.name << ": the value is nowhere material_numbers reads";
    ++checked;
  }
}

// Each valued input of every closure writes its own parameter's place, and no other.
TEST(ClosureInputs, EverySocketLandsWhereCompilingPutsItsParameter) {
  size_t sockets = 0, checked = 0;
  for_each_alternative<NodeVariant>([&]<class D>(std::type_identity<D>) {
    if constexpr (kIsClosure<D>) {
      for (const SocketInfo& s : node_inputs_of<D>()) sockets += s.has_value;
      std::apply([&](const auto&... r) { (check_row<D>(r, checked), ...); }, ParamTable<D>::rows);
    }
  });
  EXPECT_EQ(checked, sockets);
  EXPECT_GE(checked, 20u);
}

}  // namespace
}  // namespace inkray
