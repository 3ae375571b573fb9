#include "ui/model/panel_layout.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace inkray {
namespace {

// Below these the panels stop being usable; in points.
constexpr float kMinSide = 180.f;
constexpr float kMinCentre = 320.f;
constexpr float kMinViewportHeight = 160.f;
constexpr float kMinBottom = 120.f;

float finite_or(float v, float fallback) { return std::isfinite(v) ? v : fallback; }

}  // namespace

const PanelRect& PanelRects::operator[](Panel p) const {
  // In Panel's order.
  static constexpr PanelRect PanelRects::*kRects[] = {&PanelRects::scene,       &PanelRects::viewport,
                                                      &PanelRects::output,      &PanelRects::properties,
                                                      &PanelRects::node_editor, &PanelRects::timeline};
  static_assert(std::size(kRects) == size_t(Panel::timeline) + 1);
  return this->*kRects[size_t(p)];
}

PanelLayout sanitized(PanelLayout l) {
  const PanelLayout d;
  l.scene_width = std::clamp(finite_or(l.scene_width, d.scene_width), kMinSide, 2000.f);
  l.properties_width = std::clamp(finite_or(l.properties_width, d.properties_width), kMinSide, 2000.f);
  l.output_height = std::clamp(finite_or(l.output_height, d.output_height), kMinBottom, 2000.f);
  l.node_split = std::clamp(finite_or(l.node_split, d.node_split), 0.15f, 0.85f);
  return l;
}

PanelRects place_panels(const PanelLayout& stored, float width, float height, float top, float scale,
                        bool node_editor_open) {
  const PanelLayout l = sanitized(stored);
  const float body = std::max(height - top, 1.f);
  // Side panels share what the centre's minimum leaves, in proportion to their stored widths.
  float scene_w = l.scene_width * scale, props_w = l.properties_width * scale;
  const float side_room = std::max(width - kMinCentre * scale, 2.f * kMinSide * scale);
  if (scene_w + props_w > side_room) {
    const float shrink = side_room / (scene_w + props_w);
    scene_w *= shrink, props_w *= shrink;
  }
  scene_w = std::floor(scene_w), props_w = std::floor(props_w);
  const float centre_w = std::max(width - scene_w - props_w, 1.f);
  const float right_x = scene_w + centre_w;

  const float timeline_h = std::floor(kTimelineHeight * scale);
  PanelRects r;
  if (!node_editor_open) {
    const float room = std::max(body - timeline_h - kMinViewportHeight * scale, kMinBottom * scale);
    const float bottom_h = std::floor(std::clamp(l.output_height * scale, kMinBottom * scale, room));
    const float viewport_h = std::max(body - bottom_h - timeline_h, 1.f);
    r.scene = {0, top, scene_w, body};
    r.viewport = {scene_w, top, centre_w, viewport_h};
    r.timeline = {scene_w, top + viewport_h, centre_w, timeline_h};
    r.output = {scene_w, top + viewport_h + timeline_h, centre_w, body - viewport_h - timeline_h};
    r.properties = {right_x, top, props_w, body};
    return r;
  }
  // The node editor spans the scene and viewport columns below them; the output tabs
  // move under the properties, since nodes need width more than the log does.
  // The split is the viewport's and the timeline's share together.
  const float viewport_h = std::floor(
      std::min(std::max(body * l.node_split, kMinViewportHeight * scale * 0.75f + timeline_h), body * 0.85f));
  const float bottom_h = std::floor(
      std::clamp(l.output_height * scale, kMinBottom * scale, std::max(body * 0.6f, kMinBottom * scale)));
  r.scene = {0, top, scene_w, viewport_h};
  r.viewport = {scene_w, top, centre_w, std::max(viewport_h - timeline_h, 1.f)};
  r.timeline = {scene_w, top + r.viewport.h, centre_w, timeline_h};
  r.node_editor = {0, top + viewport_h, right_x, body - viewport_h};
  r.properties = {right_x, top, props_w, body - bottom_h};
  r.output = {right_x, top + body - bottom_h, props_w, bottom_h};
  return r;
}

PanelLayout resized(const PanelLayout& layout, Panel panel, const PanelRects& placed,
                    const PanelRect& dragged, float scale, bool node_editor_open) {
  // Sizes restart from what is on screen (the stored ones may have been squeezed to fit).
  PanelLayout l = layout;
  const float s = std::max(scale, 0.1f);
  const PanelRect& was = placed[panel];
  const float dw = dragged.w - was.w, dh = dragged.h - was.h;
  const bool left_edge = dragged.x != was.x, top_edge = dragged.y != was.y;
  const bool right_edge = !left_edge && dw != 0.f, bottom_edge = !top_edge && dh != 0.f;
  const float body = placed.scene.h + (node_editor_open ? placed.node_editor.h : 0.f);
  const auto scene_w = [&](float delta) { l.scene_width = (placed.scene.w + delta) / s; };
  const auto props_w = [&](float delta) { l.properties_width = (placed.properties.w + delta) / s; };
  const auto output_h = [&](float delta) { l.output_height = (placed.output.h + delta) / s; };
  // The scene list is as tall as the viewport and the timeline under it.
  const auto split = [&](float delta) { l.node_split = (placed.scene.h + delta) / std::max(body, 1.f); };
  switch (panel) {
    case Panel::scene:
      if (right_edge) scene_w(dw);
      if (bottom_edge && node_editor_open) split(dh);
      break;
    case Panel::properties:
      if (left_edge) props_w(dw);
      if (bottom_edge && node_editor_open) output_h(-dh);
      break;
    case Panel::viewport:
      if (left_edge) scene_w(-dw);
      if (right_edge) props_w(-dw);
      if (bottom_edge) node_editor_open ? split(dh) : output_h(-dh);
      break;
    case Panel::output:
      if (top_edge) output_h(dh);
      if (node_editor_open) {
        if (left_edge) props_w(dw);
      } else {
        if (left_edge) scene_w(-dw);
        if (right_edge) props_w(-dw);
      }
      break;
    case Panel::node_editor:
      if (top_edge) split(-dh);
      if (right_edge) props_w(-dw);
      break;
    case Panel::timeline:
      break;  // a fixed height, drawn without resize borders
  }
  return sanitized(l);
}

}  // namespace inkray
