// Finds path fields the way scene_checks does, through the parameter tables, so a new
// asset type needs no change here.
#include "core/document/asset_paths.h"

#include "core/document/asset_probe.h"
#include "core/document/error_log.h"
#include "core/document/tagged_variant.h"

#include <string>
#include <type_traits>
#include <utility>

namespace inkray {
namespace {

namespace fs = std::filesystem;

// Walks a scene, or a const one with const paths: Visit takes `std::string&` or
// `const std::string&` accordingly.
template <class Visit>
struct PathFinder {
  std::string at;  // JSON path of the struct being visited
  const AssetSite& owner;
  const Visit& f;

  template <class T>
  void operator()(const Param& p, T& field) {
    using U = std::remove_const_t<T>;
    if constexpr (std::is_same_v<U, std::string>) {
      if (p.kind != ParamKind::path) return;
      AssetSite site = owner;
      site.at = child_path(at, p.name);
      site.type = p.file_type;
      f(site, field);
    } else if constexpr (std::is_same_v<U, ColorInput>) {
      visit_tagged(child_path(at, p.name), field);
    } else if constexpr (std::is_same_v<U, std::vector<GraphNodeDesc>>) {
      for (size_t i = 0; i < field.size(); ++i)
        visit_tagged(element_path(child_path(at, p.name), i), field[i].data);
    } else if constexpr (requires(PathFinder & inner) { visit_params(field, inner); }) {
      PathFinder inner{child_path(at, p.name), owner, f};  // a group
      visit_params(field, inner);
    } else if constexpr (requires(PathFinder & inner) { visit_params(field.front(), inner); }) {
      for (size_t i = 0; i < field.size(); ++i) {  // a list
        PathFinder inner{element_path(child_path(at, p.name), i), owner, f};
        visit_params(field[i], inner);
      }
    }
  }

  template <class Variant>
  void visit_tagged(const std::string& path, Variant& value) {
    std::visit(
        [&]<class A>(A& alternative) {
          if constexpr (Tagged<std::remove_const_t<A>>) {
            PathFinder inner{path, owner, f};
            visit_params(alternative, inner);
          }
        },
        value);
  }
};

std::string rebase(const std::string& written, const fs::path& from, const fs::path& to) {
  if (written.empty() || written.find('\0') != std::string::npos) return written;
  const fs::path p(written);
  if (p.is_absolute()) return written;
  const fs::path target = (from / p).lexically_normal();
  const fs::path relative = target.lexically_relative(to);
  return (relative.empty() ? target : relative).generic_string();
}

template <class Scene, class Visit>
void walk_asset_paths(Scene& scene, const Visit& f) {
  using Finder = PathFinder<Visit>;
  // `may_name` passes over items that name no file (most objects of a large scene)
  // without building their paths.
  const auto section = [&](auto& items, const char* name, const char* noun, auto&& visit, auto&& may_name) {
    for (size_t i = 0; i < items.size(); ++i) {
      if (!may_name(std::as_const(items[i]))) continue;
      const AssetSite owner{{}, std::string(noun) + " " + in_quotes(items[i].name)};
      visit(element_path(name, i), items[i], owner);
    }
  };
  const auto every = [](const auto&) { return true; };
  // Materials and lights: the paths are their variant's, under the item's own path.
  const auto data = [&](const std::string& at, auto& item, const AssetSite& owner) {
    Finder{{}, owner, f}.visit_tagged(at, item.data);
  };
  const AssetSite environment{{}, "the environment"};
  Finder{{}, environment, f}.visit_tagged("environment", scene.environment);
  section(scene.materials, "materials", "material", data, every);
  section(
      scene.objects, "objects", "object",
      [&](const std::string& at, auto& o, const AssetSite& owner) {
        Finder finder{at, owner, f};
        visit_params(o, finder);
        finder.visit_tagged(at + ".shape", o.shape);
      },
      [](const auto& o) { return may_name_files(o) || may_name_files(o.shape); });
  section(scene.lights, "lights", "light", data, every);
  section(
      scene.strokes, "strokes", "stroke emitter",
      [&](const std::string& at, auto& s, const AssetSite& owner) {
        // An emitter's one path is its brush image, read only by the image brush.
        AssetSite emitter = owner;
        emitter.in_use = s.brush == BrushKind::image;
        Finder finder{at, emitter, f};
        visit_params(s, finder);
      },
      every);
  section(
      scene.outlines.sets, "outlines.sets", "line set",
      [&](const std::string& at, auto& set, const AssetSite& owner) {
        // A set's one path is its brush image, read only by the image brush.
        AssetSite line_set = owner;
        line_set.in_use = set.style.brush == LineBrush::image;
        Finder finder{at, line_set, f};
        visit_params(set, finder);
      },
      every);
}

}  // namespace

void for_each_asset_path(SceneDesc& scene,
                         const std::function<void(const AssetSite&, std::string& path)>& f) {
  walk_asset_paths(scene, f);
}

void for_each_asset_path(const SceneDesc& scene,
                         const std::function<void(const AssetSite&, const std::string& path)>& f) {
  walk_asset_paths(scene, f);
}

void rebase_asset_paths(SceneDesc& scene, const fs::path& from_dir, const fs::path& to_dir) {
  const fs::path from = fs::absolute(from_dir).lexically_normal();
  const fs::path to = fs::absolute(to_dir).lexically_normal();
  if (from == to) return;
  for_each_asset_path(scene, [&](const AssetSite&, std::string& path) { path = rebase(path, from, to); });
}

}  // namespace inkray
