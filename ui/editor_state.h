// What the editor's panels share: the document, the selection, the log and the
// viewport's settings. Panels read and change it; the app shell turns changes
// into renderer calls once per frame. No window or GL here.
#pragma once

#include "core/render/export_job.h"
#include "core/render/progressive_renderer.h"
#include "ui/document.h"
#include "ui/log.h"
#include "ui/selection.h"

#include <memory>

namespace inkray {

class MaterialSwatches;  // ui/material_swatches.h: needs GL, so the app owns it

struct ExportSettings {
  std::string output = "render.png";
  int spp = 256;
  float time_limit = 0.f;
  std::vector<bool> aovs = std::vector<bool>(kAovNames.size(), false);
};

struct EditorState {
  Document document;
  Selection selection;
  Log log;
  ViewportView view;
  // Zero spp and time follow the document's render settings.
  ViewportLimits limits{0, 0.0, 0.0};
  RegionRect region;
  bool paused = false;
  CameraDesc home_camera;  // "Reset camera" returns here: the camera the document opened with
  bool region_tool = false;  // left drag in the viewport draws a render region instead of orbiting
  // Why the newest document cannot render (an unset file, a dangling name), shown over
  // the viewport until a document that renders replaces it.
  std::vector<std::string> render_problems;
  ExportSettings export_settings;
  MaterialSwatches* swatches = nullptr;  // the app's material previews; null without a GL context (tests)
  std::unique_ptr<ExportJob> export_job;

  // Requests to the app shell, which owns dialogs and the renderer.
  bool want_frame_selected = false;
  bool want_add_mesh = false;
  bool want_export = false;
  bool want_node_editor = false;  // the properties panel's "Edit nodes"

  // Edits go through the document so they can be undone.
  void edit(SceneDesc after, std::string label, std::string merge_key = {}) {
    document.edit(std::move(after), std::move(label), std::move(merge_key));
  }
};

}  // namespace inkray
