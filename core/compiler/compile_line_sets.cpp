// Line sets compiled (compile_line_sets.h).
#include "core/compiler/compile_line_sets.h"

#include "core/npr/strokes/brush.h"
#include "core/world/line_types.h"

#include <algorithm>

namespace inkray {
namespace {

bool glob(std::string_view text, std::string_view pattern) {
  // Iterative wildcard match: the last * absorbs what follows it, back-tracking once per character.
  size_t t = 0, p = 0, star = std::string_view::npos, mark = 0;
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++t, ++p;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++, mark = t;
    } else if (star != std::string_view::npos) {
      p = star + 1, t = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

template <class Items>
std::vector<bool> select_names(const Items& items, std::string_view patterns) {
  if (trim(patterns).empty()) return {};
  std::vector<bool> chosen(items.size(), false);
  for (size_t i = 0; i < items.size(); ++i) chosen[i] = matches_patterns(items[i].name, patterns);
  return chosen;
}

uint32_t type_bits(const LineTypeChoice& c) {
  const std::array<bool, kLineTypeCount> on = {c.depth,    c.crease, c.intersection,
                                               c.material, c.object, c.silhouette};
  uint32_t bits = 0;
  for (int t = 0; t < kLineTypeCount; ++t)
    if (on[size_t(t)]) bits |= 1u << t;
  return bits;
}

uint32_t path_bits(const LinePathChoice& c) {
  return (c.direct ? 1u << int(LinePath::direct) : 0u) | (c.reflected ? 1u << int(LinePath::reflected) : 0u) |
         (c.refracted ? 1u << int(LinePath::refracted) : 0u);
}

}  // namespace

bool matches_patterns(std::string_view name, std::string_view patterns) {
  if (trim(patterns).empty()) return true;
  while (true) {
    const size_t comma = patterns.find(',');
    const std::string_view one = trim(patterns.substr(0, comma));
    if (!one.empty() && glob(name, one)) return true;
    if (comma == std::string_view::npos) return false;
    patterns.remove_prefix(comma + 1);
  }
}

LineBrushLoader read_line_brushes(const std::filesystem::path& base_dir) {
  return
      [base_dir](const StrokeEmitterDesc& brush, std::string* error) -> std::shared_ptr<const AlphaTexture> {
        return make_brush_mask(brush, base_dir, error);
      };
}

std::vector<LineSet> compile_line_sets(const SceneDesc& desc, const LineBrushLoader& brushes,
                                       std::vector<std::string>* errors) {
  std::vector<LineSet> sets;
  for (size_t i = 0; i < desc.outlines.sets.size(); ++i) {
    const LineSetDesc& d = desc.outlines.sets[i];
    if (!d.enabled) continue;
    LineSet set;
    set.name = d.name;
    set.select.types = type_bits(d.types);
    set.select.paths = path_bits(d.paths);
    set.select.visible = d.visibility != LineVisibility::hidden;
    set.select.hidden = d.visibility != LineVisibility::visible;
    set.select.objects = select_names(desc.objects, d.objects);
    set.select.materials = select_names(desc.materials, d.materials);
    static_cast<LineStyleParams&>(set.style) = d.style;
    if (d.style.brush != LineBrush::none) {
      // A line's brush is a stroke's: one brush for both keeps one place that reads them.
      StrokeEmitterDesc brush;
      brush.brush = d.style.brush == LineBrush::bristle ? BrushKind::bristle
                    : d.style.brush == LineBrush::flat  ? BrushKind::flat
                                                        : BrushKind::image;
      brush.brush_image = d.style.brush_image;
      brush.pressure = kLineBrushPressure;
      std::string error;
      set.style.brush = brushes(brush, &error);
      if (!set.style.brush && errors)
        errors->push_back("outlines.sets[" + std::to_string(i) + "].style.brush_image: " + error);
    }
    sets.push_back(std::move(set));
  }
  return sets;
}

std::vector<uint8_t> line_material_paths(const SceneDesc& desc) {
  std::vector<uint8_t> paths;
  for (size_t i = 0; i < desc.materials.size(); ++i) {
    const MaterialDesc& m = desc.materials[i];
    LinePath p = LinePath::direct;
    if (std::holds_alternative<ConductorDesc>(m.data)) p = LinePath::reflected;
    if (std::holds_alternative<DielectricDesc>(m.data)) p = LinePath::refracted;
    paths.push_back(uint8_t(p));
  }
  return paths;
}

}  // namespace inkray
