#include "core/compiler/compile_view.h"

#include "core/npr/outlines/outline_styles.h"

#include <algorithm>

namespace inkray {
namespace {

// The outline width in pixels of an image 1080 lines tall, as a line set's style has it.
// A width in world units has no one size in the image: two pixels stand for it.
float plain_width_1080(const OutlineDesc& o) {
  switch (o.unit) {
    case LineWidthUnit::pixels:
      return o.width * 1080.f / std::max(o.reference_height, 1.f);
    case LineWidthUnit::percent:
      return o.width * 1080.f / 100.f;
    case LineWidthUnit::world:
      break;
  }
  return 2.f;
}

}  // namespace

SampleSettings compile_sample_settings(const RenderSettings& render) {
  SampleSettings s;
  s.width = render.width;
  s.height = render.height;
  s.max_depth = render.max_depth;
  s.seed = uint32_t(render.seed);
  s.clamp = render.clamp;
  s.filter = render.filter;
  s.filter_radius = render.filter_radius;
  s.motion_blur = render.motion_blur();
  return s;
}

ResolveSettings compile_resolve_settings(const RenderSettings& render, const OutlineDesc& outlines) {
  ResolveSettings r;
  r.painterly = render.painterly;
  r.painterly_radius = render.painterly_radius;
  r.painterly_sharpness = render.painterly_sharpness;
  for (int t = 0; t < kLineTypeCount; ++t) {
    const LineStyleDesc& style = line_style(outlines, LineType(t));
    r.lines[size_t(t)] = {style.color, style.opacity};
    if (!outlines.enabled || !style.enabled) continue;
    LineSet plain;
    plain.name = kLineTypeNames[size_t(t)];
    plain.select.types = 1u << t;
    plain.style.color = style.color;
    plain.style.opacity = style.opacity;
    plain.style.width = plain_width_1080(outlines) * style.width;
    r.plain_sets.push_back(std::move(plain));
  }
  return r;
}

ResolveSettings compile_resolve_settings(const SceneDesc& desc, const LineBrushLoader& brushes,
                                         std::vector<std::string>* errors) {
  ResolveSettings r = compile_resolve_settings(desc.render, desc.outlines);
  r.sets = compile_line_sets(desc, brushes, errors);
  if (!r.sets.empty()) r.material_paths = line_material_paths(desc);
  return r;
}

}  // namespace inkray
