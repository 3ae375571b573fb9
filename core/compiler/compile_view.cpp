#include "core/compiler/compile_view.h"

#include "core/npr/outlines/outline_styles.h"

namespace inkray {

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
  }
  return r;
}

}  // namespace inkray
