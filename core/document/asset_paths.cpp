// Finds path fields the way scene_checks does, through visit_params, so a new
// asset type needs no change here.
#include "core/document/asset_paths.h"

#include "core/document/tagged_variant.h"

#include <string>
#include <type_traits>

namespace inkray {
namespace {

namespace fs = std::filesystem;

struct Rebaser {
  const fs::path& from;  // absolute, normalised
  const fs::path& to;    // absolute, normalised

  template <class T>
  void operator()(const Param& p, T& field) {
    if constexpr (std::is_same_v<T, std::string>) {
      if (p.kind == ParamKind::path) field = rebase(field);
    } else if constexpr (std::is_same_v<T, ColorInput>) {
      visit_tagged(field);
    } else if constexpr (std::is_same_v<T, std::vector<GraphNodeDesc>>) {
      for (GraphNodeDesc& node : field) visit_tagged(node.data);
    }
  }

  template <class Variant>
  void visit_tagged(Variant& value) {
    std::visit(
        [&]<class A>(A& alternative) {
          if constexpr (Tagged<A>) visit_params(alternative, *this);
        },
        value);
  }

  std::string rebase(const std::string& written) const {
    if (written.empty() || written.find('\0') != std::string::npos) return written;
    const fs::path p(written);
    if (p.is_absolute()) return written;
    const fs::path target = (from / p).lexically_normal();
    const fs::path relative = target.lexically_relative(to);
    return (relative.empty() ? target : relative).generic_string();
  }
};

}  // namespace

void rebase_asset_paths(SceneDesc& scene, const fs::path& from_dir, const fs::path& to_dir) {
  const fs::path from = fs::absolute(from_dir).lexically_normal();
  const fs::path to = fs::absolute(to_dir).lexically_normal();
  if (from == to) return;
  Rebaser r{from, to};
  r.visit_tagged(scene.environment);
  for (auto& m : scene.materials) r.visit_tagged(m.data);
  for (auto& o : scene.objects) r.visit_tagged(o.shape);
  for (auto& l : scene.lights) r.visit_tagged(l.data);
  for (auto& s : scene.strokes) visit_params(s, r);
}

}  // namespace inkray
