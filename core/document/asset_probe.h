// Whether a value may name a file: a path parameter anywhere within it, or a colour
// input or graph node that is a texture. Found through the parameter tables, as the
// walkers of scene_checks.cpp and asset_paths.cpp find the files themselves, but
// without building a JSON path: most objects of a large scene (spheres, quads,
// boxes) name none, and those walks pass them over.
#pragma once

#include "core/document/desc.h"
#include "core/document/tagged_variant.h"

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace inkray {

struct AssetProbe {
  bool found = false;

  template <class T>
  void operator()(const Param& p, const T& field) {
    if (found) return;
    if constexpr (std::is_same_v<T, std::string>) {
      found = p.kind == ParamKind::path;
    } else if constexpr (std::is_same_v<T, std::vector<GraphNodeDesc>>) {
      for (const GraphNodeDesc& node : field) tagged(node.data);
    } else if constexpr (requires { std::visit([](const auto&) {}, field); }) {
      tagged(field);
    } else if constexpr (requires(AssetProbe & inner) { visit_params(field, inner); }) {
      visit_params(field, *this);
    } else if constexpr (requires(AssetProbe & inner) { visit_params(field.front(), inner); }) {
      for (const auto& item : field) visit_params(item, *this);
    }
  }

  template <class Variant>
  void tagged(const Variant& value) {
    std::visit(
        [&]<class A>(const A& alternative) {
          if constexpr (Tagged<A>) visit_params(alternative, *this);
        },
        value);
  }
};

// For a struct with a parameter table, or a variant of tagged alternatives (a shape).
template <class T>
bool may_name_files(const T& value) {
  AssetProbe probe;
  if constexpr (requires { std::visit([](const auto&) {}, value); })
    probe.tagged(value);
  else
    visit_params(value, probe);
  return probe.found;
}

}  // namespace inkray
