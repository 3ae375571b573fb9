#include "app/scripted_run.h"

#include "core/document/json_io.h"
#include "core/image/image_io.h"
#include "core/io/atomic_file.h"
#include "core/math/color_space.h"
#include "ui/widgets/widget_report.h"

#include <GL/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace inkray {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool write_screenshot(const std::string& file, int width, int height) {
  std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  RgbImage image{width, height, std::vector<Color>(size_t(width) * size_t(height))};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &rgba[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4];  // GL rows go up
      image.at(x, y) =
          Color(srgb_to_linear(p[0] / 255.f), srgb_to_linear(p[1] / 255.f), srgb_to_linear(p[2] / 255.f));
    }
  }
  std::string error;
  if (!write_image(file, image, &error)) {
    std::fprintf(stderr, "inkray: %s\n", error.c_str());
    return false;
  }
  return true;
}

bool write_text(const std::string& file, const std::string& text) {
  std::string error;
  if (write_file_atomically(file, text, &error)) return true;
  std::fprintf(stderr, "inkray: %s\n", error.c_str());
  return false;
}

// Selects the entry of `items` named `name`, the value of `option` (empty: not given,
// nothing to select); false, having said so, when there is no such `what`.
template <class Items>
bool select_named(EditorState& state, const Items& items, ItemKind kind, const std::string& name,
                  const char* option, const char* what) {
  if (name.empty()) return true;
  const auto found =
      std::find_if(items.begin(), items.end(), [&](const auto& item) { return item.name == name; });
  if (found == items.end()) {
    std::fprintf(stderr, "inkray: %s: no %s named \"%s\"\n", option, what, name.c_str());
    return false;
  }
  state.selection = {kind, int(found - items.begin())};
  return true;
}

}  // namespace

ScriptedRun::ScriptedRun(ScriptOptions options) : opt_(std::move(options)) {
  widget_report::enable(!opt_.widget_report.empty());
}

ScriptedRun::~ScriptedRun() = default;

bool ScriptedRun::start(EditorApp& app) {
  started_ = now_seconds();
  EditorState& state = app.state();
  const SceneDesc& scene = state.document.scene();
  if (!select_named(state, scene.objects, ItemKind::object, opt_.select, "--select", "object") ||
      !select_named(state, scene.materials, ItemKind::material, opt_.node_material, "--node-editor",
                    "material")) {
    exit_code_ = 1;
    return false;
  }
  if (!opt_.node_material.empty()) app.show_node_editor(true);
  if (opt_.measure_edits > 0) {
    std::vector<measure::EditKind> kinds;
    for (measure::EditKind kind : opt_.edit_kinds.empty()
                                      ? std::vector<measure::EditKind>{measure::EditKind::camera}
                                      : opt_.edit_kinds) {
      if (const std::string why = measure::unavailable(kind, state.document.scene()); !why.empty()) {
        std::fprintf(stderr, "inkray: --edit %s: %s\n",
                     std::string(measure::kEditKindNames[size_t(kind)]).c_str(), why.c_str());
        kind_skipped_ = true;
      } else {
        kinds.push_back(kind);
      }
    }
    if (kinds.empty()) {
      exit_code_ = 1;
      return false;
    }
    measurement_ = std::make_unique<measure::EditMeasurement>(std::move(kinds), opt_.measure_edits);
  }
  return true;
}

void ScriptedRun::before_frame(EditorApp& app, int frame) {
  widget_report::begin_frame();
  if (frame == 1 && !opt_.drops.empty()) {
    std::vector<std::filesystem::path> files(opt_.drops.begin(), opt_.drops.end());
    app.drop(std::move(files));
  }
}

// Starts the export at the first frame and notes the frame it ended at. False when it
// could not start or failed.
bool ScriptedRun::track_export(EditorApp& app, int frame) {
  if (opt_.export_path.empty()) return true;
  if (frame == 1) {
    export_id_ = app.export_ui().start_for_test(app.state(), opt_.export_path);
    if (export_id_ == 0) {
      std::fprintf(stderr, "inkray: --export: %s\n", app.export_ui().dialog_error().c_str());
      return false;
    }
  }
  if (export_id_ == 0 || export_finished_frame_ >= 0) return true;
  const ExportEntry* e = app.export_ui().queue().find(export_id_);
  if (e && e->state != ExportState::done && e->state != ExportState::failed &&
      e->state != ExportState::cancelled)
    return true;
  export_finished_frame_ = frame;
  if (!e || e->state != ExportState::done) {
    std::fprintf(stderr, "inkray: --export: %s\n", e ? e->error.c_str() : "the export vanished");
    return false;
  }
  std::printf("export: %d threads, %u spp in %.2f s\n", e->progress.threads, e->progress.spp,
              e->progress.elapsed_seconds);
  for (const auto& f : e->written) std::printf("export wrote: %s\n", f.string().c_str());
  return true;
}

// The screenshot and the reports that go with it; false when one could not be written.
bool ScriptedRun::write_outputs(EditorApp& app, int width, int height) {
  const auto& v = app.viewport_frame();
  std::printf("viewport image: %d %d %d %d\n", int(v.image_x), int(v.image_y), int(v.image_w),
              int(v.image_h));
  std::printf("viewport spp: %u\n", app.viewport().shown_spp());
  std::printf("viewport denoised: %d\n", app.viewport().shown_denoised() ? 1 : 0);
  std::printf("ui scale: %.2f\n", app.ui_scale());
  bool ok = write_screenshot(opt_.screenshot, width, height);
  if (!opt_.node_layout.empty()) ok = write_text(opt_.node_layout, app.node_editor().layout()) && ok;
  if (!opt_.scene_dump.empty())
    ok = write_text(opt_.scene_dump, scene_to_string(app.state().document.scene())) && ok;
  if (!opt_.widget_report.empty()) {
    const std::string window = "window 0 0 " + std::to_string(width) + " " + std::to_string(height) + "\n";
    ok = write_text(opt_.widget_report, window + widget_report::text()) && ok;
  }
  return ok;
}

bool ScriptedRun::after_frame(EditorApp& app, int frame, int width, int height, double work_ms) {
  if (!track_export(app, frame)) {
    exit_code_ = 1;
    return false;
  }
  if (!opt_.screenshot.empty()) {
    const bool export_settled =
        opt_.export_path.empty() || (export_finished_frame_ >= 0 && frame >= export_finished_frame_ + 5);
    // The full-resolution image, or two minutes without it: the screenshot shows what there is.
    const bool image_ready = app.viewport().shown_full_resolution() || now_seconds() - started_ > 120.0;
    if (frame >= opt_.frames && export_settled && image_ready) {
      exit_code_ = write_outputs(app, width, height) ? 0 : 1;
      return false;
    }
  }
  if (measurement_ && !measurement_->step(app, work_ms)) {
    if (measurement_->failed() || kind_skipped_) exit_code_ = 1;
    return false;
  }
  if (opt_.interactive() && opt_.frames > 0 && frame >= opt_.frames) return false;
  return true;
}

}  // namespace inkray
