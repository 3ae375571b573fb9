// inkray --measure-edits: makes edits of each kind as a slider drag would, follows each
// to the first image on screen that shows it, and prints per kind
// `edit KIND: first pixels p50 X ms p95 Y ms; frame p95 Z ms; samples kept S`.
#pragma once

#include "ui/editor_app.h"
#include "ui/viewport/gizmo.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace inkray::measure {

using Clock = std::chrono::steady_clock;

// What --measure-edits changes: each a small step, as one frame of a slider drag makes.
// `node` is a value on a node of the first material graph an object uses. `gizmo-drag`
// drags the first object's translate gizmo along an axis, a step every frame, through
// the gizmo's drag maths (ui/viewport/gizmo.h) and the same undoable edit as the mouse makes.
enum class EditKind {
  camera,
  material,
  node,
  light,
  transform,
  line_colour,
  stroke_parameter,
  exposure,
  gizmo_drag
};
constexpr std::array<std::string_view, 9> kEditKindNames = {
    "camera",      "material",         "node",     "light",     "transform",
    "line-colour", "stroke-parameter", "exposure", "gizmo-drag"};

// "camera, material, ...", for help and error messages.
std::string edit_kind_list();
// Why `kind` cannot be measured on this scene; empty when it can.
std::string unavailable(EditKind kind, const SceneDesc& scene);
// "what: n=... p50=... p95=... max=..." (milliseconds).
void print_stats(const char* what, const std::vector<double>& ms);

// Makes the edits of --measure-edits, one every 15 frames (gizmo drags: every frame), follows
// each to the first image on screen that shows it, and prints a line per kind. step() runs
// once a frame, after the frame's work, and returns false when every kind is done.
class EditMeasurement {
 public:
  EditMeasurement(std::vector<EditKind> kinds, int edits) : kinds_(std::move(kinds)), edits_(edits) {}
  bool step(EditorApp& app, double work_ms);
  bool failed() const { return failed_; }

 private:
  struct Edit {
    uint64_t revision = 0;     // document edits: the submit carrying it, known the frame after
    Clock::time_point sent{};  // exposure: when set_view took it, known the frame after
    bool sent_known = false;
    uint32_t spp_before = 0;  // full-resolution samples on screen when it was made (preview: 0)
    // Exposure: the newest image known to show the old exposure, and the change in scale.
    std::shared_ptr<const ViewportSnapshot> before;
    float scale = 1.f;
  };
  EditKind kind() const { return kinds_[kind_]; }
  void start_kind(EditorApp& app);
  void make_edit(EditorApp& app);
  void grab_gizmo(EditorApp& app);
  void drag_gizmo(EditorApp& app, int step);
  void follow(EditorApp& app);
  void finish_kind(EditorApp& app);

  std::vector<EditKind> kinds_;
  int edits_;
  size_t kind_ = 0;
  bool started_ = false, failed_ = false;
  Clock::time_point waiting_since_ = Clock::now(), last_edit_time_;
  int made_ = 0, frames_since_edit_ = 0;
  SceneDesc base_;
  float base_exposure_ = 0.f, shown_exposure_ = 0.f;
  size_t latencies_begin_ = 0;
  std::vector<Edit> pending_;
  std::vector<double> frame_ms_, exposure_latencies_ms_, kept_percent_;
  std::shared_ptr<const ViewportSnapshot> seen_;  // the newest image already looked at
  // gizmo-drag: the drag, and where on screen its handle was taken and which way it runs.
  std::optional<GizmoDrag> gizmo_;
  Vec2 grab_{0.f}, along_{1.f, 0.f};
};

}  // namespace inkray::measure
