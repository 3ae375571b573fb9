#include "core/document/edit_checks.h"

#include "core/document/error_log.h"
#include "core/document/scene_checks.h"

#include <algorithm>
#include <optional>
#include <type_traits>
#include <unordered_map>
#include <utility>

namespace inkray {

Vec3 locked_scale(const Vec3& before, const Vec3& edited) {
  for (int i = 0; i < 3; ++i) {
    if (edited[i] == before[i]) continue;
    if (before[i] == 0.f || edited[i] == 0.f) return before;
    const float ratio = edited[i] / before[i];
    Vec3 scaled = before * ratio;
    scaled[i] = edited[i];  // the typed value exactly, whatever the rounding of the ratio
    return scaled;
  }
  return before;
}

void give_mix_inputs(SceneDesc& scene, size_t material) {
  if (material >= scene.materials.size() || !std::holds_alternative<MixDesc>(scene.materials[material].data))
    return;
  const std::string self = scene.materials[material].name;
  const auto usable = [&](const std::string& name) {
    return name != self &&
           std::any_of(scene.materials.begin(), scene.materials.end(), [&](const MaterialDesc& m) {
             return m.name == name && !std::holds_alternative<MixDesc>(m.data);
           });
  };
  std::vector<std::string> candidates;
  for (const MaterialDesc& m : scene.materials)
    if (usable(m.name) && std::find(candidates.begin(), candidates.end(), m.name) == candidates.end())
      candidates.push_back(m.name);
  const auto taken = [&](const std::string& name) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [&](const MaterialDesc& m) { return m.name == name; });
  };
  // Inputs named well stay; the others take a candidate not used by the other side.
  MixDesc mix = std::get<MixDesc>(scene.materials[material].data);
  for (std::string* side : {&mix.a, &mix.b}) {
    if (usable(*side)) continue;
    const std::string& other = side == &mix.a ? mix.b : mix.a;
    const auto free =
        std::find_if(candidates.begin(), candidates.end(), [&](const std::string& n) { return n != other; });
    if (free != candidates.end()) {
      *side = *free;
      continue;
    }
    std::string name = self + (side == &mix.a ? " a" : " b");
    for (int k = 2; taken(name); ++k) name = self + (side == &mix.a ? " a" : " b") + std::to_string(k);
    scene.materials.push_back({name, DiffuseDesc{Color(side == &mix.a ? 0.8f : 0.2f)}, {}});
    candidates.push_back(name);
    *side = name;
  }
  scene.materials[material].data = mix;
}

namespace {

// Required names (a mix's materials, an object's material, an emitter's object, a
// link's ends) left empty: the reader reports them when a file says "".
struct UnsetNames {
  std::string at;
  std::vector<std::string>* out;

  template <class T>
  void operator()(const Param& p, const T& field) {
    const std::string here = child_path(at, p.name);
    if constexpr (std::is_same_v<T, std::string>) {
      if (p.required && p.kind == ParamKind::text && field.empty())
        out->push_back(here + ": must not be empty");
    } else if constexpr (std::is_same_v<T, std::vector<GraphNodeDesc>>) {
      for (size_t i = 0; i < field.size(); ++i) tagged(element_path(here, i), field[i].data, out);
    } else if constexpr (requires { visit_params(field.front(), *this); }) {
      for (size_t i = 0; i < field.size(); ++i) {
        UnsetNames inner{element_path(here, i), out};
        visit_params(field[i], inner);
      }
    } else if constexpr (ParamGroup<T>) {
      UnsetNames inner{here, out};
      visit_params(field, inner);
    }
  }

  template <class Variant>
  static void tagged(const std::string& at, const Variant& value, std::vector<std::string>* out) {
    std::visit(
        [&]<class A>(const A& alternative) {
          if constexpr (ParamGroup<A>) {
            UnsetNames inner{at, out};
            visit_params(alternative, inner);
          }
        },
        value);
  }
};

}  // namespace

namespace {

std::vector<std::string> scoped_problems(const SceneDesc& scene, const CheckScope* scope) {
  ErrorLog log("", ReadFor::editing);
  check_scene(scene, scene.base_dir, log, scope);
  std::vector<std::string> problems = log.take();
  for (std::string& warning : log.take_warnings()) problems.push_back(std::move(warning));
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (scope && !scope->materials[i]) continue;
    UnsetNames::tagged(element_path("materials", i), scene.materials[i].data, &problems);
  }
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    if (scope && !scope->objects[i]) continue;
    UnsetNames names{element_path("objects", i), &problems};
    visit_params(scene.objects[i], names);
  }
  for (size_t i = 0; i < scene.strokes.size(); ++i) {
    if (scope && !scope->strokes[i]) continue;
    UnsetNames names{element_path("strokes", i), &problems};
    visit_params(scene.strokes[i], names);
  }
  return problems;
}

}  // namespace

std::vector<std::string> scene_problems(const SceneDesc& scene) { return scoped_problems(scene, nullptr); }

std::vector<std::string> problems_added(const SceneDesc& before, const SceneDesc& after) {
  // An edit that keeps every name (a parameter, a transform) is checked on the items it
  // changed; one that adds, removes or renames items on the whole document.
  std::optional<CheckScope> scope;
  if (same_names(before, after)) scope = changed_items(before, after);
  const CheckScope* in = scope ? &*scope : nullptr;
  std::unordered_map<std::string, int> known;
  for (std::string& p : scoped_problems(before, in)) ++known[std::move(p)];
  std::vector<std::string> added;
  for (std::string& p : scoped_problems(after, in)) {
    int& count = known[p];
    if (count > 0) {
      --count;
    } else {
      added.push_back(std::move(p));
    }
  }
  return added;
}

}  // namespace inkray
