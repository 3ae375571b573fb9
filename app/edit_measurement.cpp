#include "app/edit_measurement.h"

#include "core/image/image_io.h"
#include "ui/viewport/camera_controller.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

namespace inkray::measure {
namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
}

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// 1, 2, ..., 20, 19, ..., 0, 1, ...: a slider dragged to and fro; no two edits in a row are equal.
int drag_step(int i) {
  constexpr int kSpan = 20;
  const int p = i % (2 * kSpan);
  return p < kSpan ? p + 1 : 2 * kSpan - p - 1;
}

// 1% darker a step (colour inputs are at most 1); black grows instead.
Color nudged(Color c, int step) {
  if (std::max({c.r, c.g, c.b}) <= 0.f) return Color(0.01f * float(step));
  return c * (1.f - 0.01f * float(step));
}

void nudge(ColorInput& input, int step) {
  std::visit(
      [&](auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Color>) {
          v = nudged(v, step);
        } else if constexpr (std::is_same_v<T, ImageTextureDesc>) {
          v.scale = nudged(v.scale, step);
        } else {
          v.even = nudged(v.even, step);
        }
      },
      input);
}

// The colour a material's swatch in the properties panel would show.
void nudge(MaterialVariant& material, int step);

// A node edit: the first colour constant of the graph, as an artist dragging it.
void nudge_graph(GraphDesc& graph, int step) {
  for (GraphNodeDesc& node : graph.nodes) {
    if (auto* rgb = std::get_if<RgbNode>(&node.data)) {
      rgb->color = nudged(rgb->color, step);
      return;
    }
  }
  for (GraphNodeDesc& node : graph.nodes) {
    const bool done = std::visit(
        [&](auto& d) {
          using T = std::decay_t<decltype(d)>;
          if constexpr (std::is_constructible_v<MaterialVariant, T> && !std::is_same_v<T, GraphDesc>) {
            MaterialVariant m = d;
            nudge(m, step);
            d = std::get<T>(m);
            return true;
          }
          return false;
        },
        node.data);
    if (done) return;
  }
}

void nudge(MaterialVariant& material, int step) {
  std::visit(
      [&](auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, DiffuseDesc>) {
          nudge(d.albedo, step);
        } else if constexpr (std::is_same_v<T, DielectricDesc> || std::is_same_v<T, TransparentDesc>) {
          d.tint = nudged(d.tint, step);
        } else if constexpr (std::is_same_v<T, MixDesc>) {
          nudge(d.factor, step);
        } else if constexpr (std::is_same_v<T, GraphDesc>) {
          nudge_graph(d, step);
        } else {
          nudge(d.color, step);
        }
      },
      material);
}

float& intensity(LightVariant& light) {
  return std::visit([](auto& d) -> float& { return d.intensity; }, light);
}

int first_used_graph(const SceneDesc& s) {
  for (const ObjectDesc& o : s.objects)
    for (size_t m = 0; m < s.materials.size(); ++m)
      if (s.materials[m].name == o.material && std::holds_alternative<GraphDesc>(s.materials[m].data))
        return int(m);
  return -1;
}

int first_used_material(const SceneDesc& s) {
  for (const ObjectDesc& o : s.objects) {
    for (size_t m = 0; m < s.materials.size(); ++m) {
      if (s.materials[m].name == o.material) return int(m);
    }
  }
  return -1;
}

int first_emissive(const SceneDesc& s) {
  for (size_t m = 0; m < s.materials.size(); ++m) {
    if (std::holds_alternative<EmissiveDesc>(s.materials[m].data)) return int(m);
  }
  return -1;
}

// Document edit `step` of `kind`: one parameter set from its value in `base` (the document
// when the kind started), so steps do not pile up; the camera orbits on as a drag does.
SceneDesc edited(EditKind kind, int step, const SceneDesc& base, SceneDesc s) {
  const float t = float(step);
  switch (kind) {
    case EditKind::camera:
      s.camera = orbit(s.camera, 0.02f, 0.f);
      break;
    case EditKind::node: {
      const size_t m = size_t(first_used_graph(base));
      s.materials[m].data = base.materials[m].data;
      nudge(s.materials[m].data, step);
      break;
    }
    case EditKind::material: {
      const size_t m = size_t(first_used_material(base));
      s.materials[m].data = base.materials[m].data;
      nudge(s.materials[m].data, step);
      break;
    }
    case EditKind::light:
      if (!base.lights.empty()) {
        LightVariant before = base.lights[0].data;
        intensity(s.lights[0].data) = intensity(before) * (1.f + 0.02f * t);
      } else {
        const size_t m = size_t(first_emissive(base));
        std::get<EmissiveDesc>(s.materials[m].data).strength =
            std::get<EmissiveDesc>(base.materials[m].data).strength * (1.f + 0.02f * t);
      }
      break;
    case EditKind::transform: {
      // In the scene's units (the Cornell box is in millimetres): a fraction of the view distance.
      const float unit = 0.002f * glm::length(base.camera.look_from - base.camera.look_at);
      s.objects[0].transform.translate = base.objects[0].transform.translate + Vec3(unit * t, 0.f, 0.f);
      break;
    }
    case EditKind::line_colour:
      s.outlines.silhouette.color = nudged(base.outlines.silhouette.color, step);
      break;
    case EditKind::stroke_parameter: {
      const float h = base.strokes[0].hue_jitter;
      s.strokes[0].hue_jitter = h <= 90.f ? h + 0.5f * t : h - 0.5f * t;
      break;
    }
    case EditKind::exposure:
    case EditKind::gizmo_drag:
      break;  // exposure is a view setting, not the document; drags are made by drag_gizmo
  }
  return s;
}

const char* edit_label(EditKind kind) {
  switch (kind) {
    case EditKind::camera:
      return "Orbit";
    case EditKind::material:
      return "Material colour";
    case EditKind::node:
      return "Node colour";
    case EditKind::light:
      return "Light intensity";
    case EditKind::transform:
      return "Move";
    case EditKind::line_colour:
      return "Line colour";
    case EditKind::stroke_parameter:
      return "Stroke hue jitter";
    case EditKind::exposure:
      return "Exposure";
    case EditKind::gizmo_drag:
      return "Move";
  }
  return "";
}

// Whether `now` shows `before`'s film at an exposure `scale` (2^stops) brighter, rather than
// at the same exposure. Pixel by pixel: a further pass moves pixels both ways by noise, an
// exposure change moves them one way, and a re-encode of the same film lands on the mapped
// byte exactly. Counts the pixels nearer the mapped value among those the change moves by
// two bytes or more (standard view transform).
bool shows_new_exposure(const ViewportSnapshot& before, const ViewportSnapshot& now, float scale) {
  if (now.width != before.width || now.height != before.height) return true;  // a restart: rendered anew
  std::array<int, 256> mapped{};
  for (int b = 0; b < 256; ++b) {
    const float linear = std::min(srgb_to_linear(float(b) / 255.f) * scale, 1.f);
    mapped[size_t(b)] = int(std::lround(255.f * linear_to_srgb(linear)));
  }
  size_t telling = 0, nearer_new = 0;
  for (size_t i = 0; i < now.rgba.size(); ++i) {
    if (i % 4 == 3) continue;  // alpha
    const int old_value = before.rgba[i], new_value = mapped[before.rgba[i]], value = now.rgba[i];
    if (std::abs(new_value - old_value) < 2) continue;
    ++telling;
    nearer_new += std::abs(value - new_value) < std::abs(value - old_value);
  }
  return telling == 0 || nearer_new * 2 > telling;
}

}  // namespace

std::string edit_kind_list() {
  std::string list;
  for (std::string_view n : kEditKindNames) list += (list.empty() ? "" : ", ") + std::string(n);
  return list;
}

std::string unavailable(EditKind kind, const SceneDesc& s) {
  switch (kind) {
    case EditKind::material:
      return first_used_material(s) < 0 ? "no object has a material to edit" : "";
    case EditKind::node:
      return first_used_graph(s) < 0 ? "no object has a material graph to edit" : "";
    case EditKind::light:
      return s.lights.empty() && first_emissive(s) < 0 ? "no light and no emissive material to edit" : "";
    case EditKind::transform:
    case EditKind::gizmo_drag:
      return s.objects.empty() ? "no object to move" : "";
    case EditKind::stroke_parameter:
      return s.strokes.empty() ? "no stroke emitter to edit" : "";
    case EditKind::camera:
    case EditKind::line_colour:
    case EditKind::exposure:
      return "";
  }
  return "";
}

void print_stats(const char* what, const std::vector<double>& v) {
  std::printf("%s: n=%zu p50=%.2f ms p95=%.2f ms max=%.2f ms\n", what, v.size(), percentile(v, 0.5),
              percentile(v, 0.95), v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()));
}

bool EditMeasurement::step(EditorApp& app, double work_ms) {
  const ViewportPanel& viewport = app.viewport();
  if (!started_) {
    // Each kind starts on a settled viewport: the newest document at full resolution.
    if (!viewport.shown_full_resolution() || viewport.shown_revision() != app.submitted_revision()) {
      if (Clock::now() - waiting_since_ < std::chrono::seconds(120)) return true;
      std::fprintf(stderr, "inkray: --measure-edits: no full-resolution image after 120 s\n");
      failed_ = true;
      return false;
    }
    start_kind(app);
  }
  frame_ms_.push_back(work_ms);
  follow(app);
  if (made_ < edits_) {
    // An exposure edit waits for the one before it to show (up to 5 s): a newer view
    // replaces an older one unseen, and each would then be measured against the wrong image.
    const bool previous_shown = kind() != EditKind::exposure || pending_.empty() ||
                                Clock::now() - last_edit_time_ > std::chrono::seconds(5);
    const int frames_apart = kind() == EditKind::gizmo_drag ? 1 : 15;
    if (++frames_since_edit_ >= frames_apart && previous_shown) {
      last_edit_time_ = Clock::now();
      frames_since_edit_ = 0;
      make_edit(app);
      if (made_ == edits_) waiting_since_ = Clock::now();
    }
    return true;
  }
  // Every edit made: wait, bounded, for the last to reach the screen.
  if (!pending_.empty() && Clock::now() - waiting_since_ < std::chrono::seconds(30)) return true;
  finish_kind(app);
  started_ = false;
  waiting_since_ = Clock::now();
  return ++kind_ < kinds_.size();
}

void EditMeasurement::start_kind(EditorApp& app) {
  started_ = true;
  base_ = app.state().document.scene();
  base_exposure_ = shown_exposure_ = app.state().view.encoding.exposure;
  latencies_begin_ = app.edit_latencies_ms().size();
  made_ = frames_since_edit_ = 0;
  pending_.clear();
  frame_ms_.clear();
  exposure_latencies_ms_.clear();
  kept_percent_.clear();
  gizmo_.reset();
  if (kind() == EditKind::gizmo_drag) grab_gizmo(app);
}

void EditMeasurement::grab_gizmo(EditorApp& app) {
  // The first object selected, as a click would, so its gizmo is drawn; the first axis
  // handle seen end to end is taken near its tip.
  EditorState& state = app.state();
  state.selection = {ItemKind::object, 0};
  const SceneDesc& scene = state.document.scene();
  const ViewportFrame& f = app.viewport_frame();
  const int w = std::max(scene.render.width, 1), h = std::max(scene.render.height, 1);
  const ViewMapping view{Camera(scene.camera, w, h), Vec2(f.image_x, f.image_y), f.image_h / float(h)};
  const GizmoFrame frame = gizmo_frame(scene.objects[0], GizmoMode::translate, view);
  for (int a = 0; a < 3; ++a) {
    const GizmoHandle handle{HandleKind::axis, a};
    Vec2 centre, tip;
    if (!handle_shown(frame, handle, view) || !view.project(frame.pivot, &centre) ||
        !view.project(frame.pivot + 0.8f * frame.length * frame.axes[size_t(a)], &tip))
      continue;
    grab_ = tip;
    along_ = glm::normalize(tip - centre);
    gizmo_.emplace(scene.objects[0], GizmoMode::translate, handle, view, grab_);
    return;
  }
}

void EditMeasurement::drag_gizmo(EditorApp& app, int step) {
  EditorState& state = app.state();
  if (!gizmo_) return;
  // 3 window pixels a step along the handle's axis on screen, out and back.
  const TransformDesc t = gizmo_->drag_to(grab_ + along_ * (3.f * float(step)), false);
  SceneDesc s = state.document.scene();
  s.objects[0].transform = t;
  state.edit(std::move(s), edit_label(EditKind::gizmo_drag), "viewport:gizmo:measure");
}

void EditMeasurement::make_edit(EditorApp& app) {
  const ViewportPanel& viewport = app.viewport();
  Edit e;
  e.spp_before = viewport.shown_full_resolution() ? viewport.shown_spp() : 0;
  const int step = drag_step(made_++);
  if (kind() == EditKind::exposure) {
    // What the toolbar's slider does; the app sends the view at the end of the next frame.
    // Its 110 pixels span 16 stops, so a drag moves it by a quarter stop or so a frame.
    float& exposure = app.state().view.encoding.exposure;
    exposure = base_exposure_ + 0.25f * float(step % 2);
    e.before = viewport.shown_snapshot();
    e.scale = std::exp2(exposure - shown_exposure_);
    // One not seen in 5 s is superseded, as a document revision is by a newer one.
    pending_.clear();
  } else if (kind() == EditKind::gizmo_drag) {
    drag_gizmo(app, step);
  } else {
    app.state().edit(edited(kind(), step, base_, app.state().document.scene()), edit_label(kind()));
  }
  pending_.push_back(e);
}

void EditMeasurement::follow(EditorApp& app) {
  const auto now = Clock::now();
  const ViewportPanel& viewport = app.viewport();
  const std::shared_ptr<const ViewportSnapshot> shown = viewport.shown_snapshot();
  const bool fresh = shown && shown != seen_;
  seen_ = shown;
  const uint64_t new_revision = app.viewport_frame().new_revision_shown;
  const auto kept = [&](const Edit& e, uint32_t spp_after) {
    if (e.spp_before > 0) kept_percent_.push_back(100.0 * double(spp_after) / double(e.spp_before));
  };
  std::vector<Edit> still;
  for (Edit& e : pending_) {
    if (kind() == EditKind::exposure) {
      // The frame after the edit sent the view; an image uploaded in it was made before.
      if (!e.sent_known) {
        e.sent = app.view_sent_time();
        e.sent_known = true;
        still.push_back(e);
        continue;
      }
      if (!fresh) {
        still.push_back(e);
        continue;
      }
      // A pass in flight may still publish at the old exposure: such an image becomes the
      // reference, and the first that shows the new exposure ends the wait.
      if (e.before && !shows_new_exposure(*e.before, *shown, e.scale)) {
        e.before = shown;
        still.push_back(e);
        continue;
      }
      exposure_latencies_ms_.push_back(ms_between(e.sent, now));
      kept(e, shown->divisor == 1 ? shown->stats.spp : 0);
      shown_exposure_ = app.state().view.encoding.exposure;
    } else {
      if (e.revision == 0) {
        e.revision = app.submitted_revision();  // submitted at the end of the frame after the edit
        still.push_back(e);
        continue;
      }
      if (new_revision == 0 || new_revision < e.revision) {
        still.push_back(e);
        continue;
      }
      // A newer revision shown first means this one was superseded: no sample.
      if (new_revision == e.revision) kept(e, viewport.shown_full_resolution() ? viewport.shown_spp() : 0);
    }
  }
  pending_ = std::move(still);
}

void EditMeasurement::finish_kind(EditorApp& app) {
  std::vector<double> latencies = exposure_latencies_ms_, renderer;
  if (kind() != EditKind::exposure) {
    const std::vector<double>& all = app.edit_latencies_ms();
    latencies.assign(all.begin() + std::ptrdiff_t(std::min(latencies_begin_, all.size())), all.end());
    const std::vector<double>& published = app.render_latencies_ms();
    renderer.assign(published.begin() + std::ptrdiff_t(std::min(latencies_begin_, published.size())),
                    published.end());
  }
  if (kinds_.size() == 1 && kind() == EditKind::camera) {
    // The summary docs/benchmarks.md quotes, over the whole run as before.
    print_stats("edit-to-first-pixels", app.edit_latencies_ms());
    print_stats("  of which renderer (compile+preview)", app.render_latencies_ms());
    print_stats("ui frame (work)", frame_ms_);
  }
  char kept[32] = "n/a";  // no edit was made on a full-resolution image and seen
  if (!kept_percent_.empty()) std::snprintf(kept, sizeof kept, "%.0f%%", percentile(kept_percent_, 0.5));
  // On screen includes presenting the window: under Xvfb each swap of a 1600x900
  // window takes llvmpipe 16-20 ms. The renderer's share ends when the image is published.
  char published[64] = "";
  if (!renderer.empty())
    std::snprintf(published, sizeof published, "; renderer p50 %.1f ms p95 %.1f ms",
                  percentile(renderer, 0.5), percentile(renderer, 0.95));
  std::printf("edit %s: first pixels p50 %.1f ms p95 %.1f ms; frame p95 %.2f ms; samples kept %s%s\n",
              std::string(kEditKindNames[size_t(kind())]).c_str(), percentile(latencies, 0.5),
              percentile(latencies, 0.95), percentile(frame_ms_, 0.95), kept, published);
  std::fflush(stdout);
}

}  // namespace inkray::measure
