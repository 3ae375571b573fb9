// What the editor's panels share: the document, the selection, the log and the
// viewport's settings. Panels read and change it; the app shell turns changes
// into renderer calls once per frame. No window or GL here.
#pragma once

#include "core/document/animation.h"
#include "core/document/edit_checks.h"
#include "core/render/progressive_renderer.h"
#include "ui/model/document.h"
#include "ui/model/log.h"
#include "ui/model/selection.h"

#include <memory>

namespace inkray {

class MaterialSwatches;  // ui/widgets/material_swatches.h: needs GL, so the app owns it
class ExportQueue;       // ui/model/export_queue.h: the app's exports

struct EditorState {
  Document document;
  Selection selection;
  Log log;
  ViewportView view;
  // Zero spp and time follow the document's render settings.
  ViewportLimits limits{0, 0.0, 0.0};
  RegionRect region;
  bool paused = false;
  CameraDesc home_camera;    // "Reset camera" returns here: the camera the document opened with
  bool region_tool = false;  // left drag in the viewport draws a render region instead of orbiting
  // Why the newest document cannot render (an unset file, a dangling name), shown over
  // the viewport until a document that renders replaces it.
  std::vector<std::string> render_problems;
  // The properties panel's last refused (or kept but unrenderable) edit: shown in red
  // beside the field it names until that item is edited again.
  Selection problem_item;
  std::string problem_param, problem_message;
  bool uniform_scale = false;            // the object transform's scale lock
  MaterialSwatches* swatches = nullptr;  // the app's material previews; null without a GL context (tests)
  // The app's exports (ui/model/export_queue.h), for the render panel's status; null until drawn.
  ExportQueue* exports = nullptr;

  // Requests to the app shell, which owns dialogs and the renderer.
  bool want_frame_selected = false;
  bool want_add_mesh = false;
  bool add_mesh_native_size = false;  // else the mesh is fitted to the view
  bool want_export = false;
  bool want_node_editor = false;  // the properties panel's "Edit nodes"
  bool want_line_sets = false;    // the properties panel's "Edit in the Line sets tab"

  // The Line sets panel's chosen set (ui/panels/line_sets_panel.h), an index into
  // outlines.sets, kept apart from `selection` so choosing a set keeps the object
  // selected; `reveal`: scroll the list to it (it was just added or moved).
  struct LineSetChoice {
    int index = 0;
    bool reveal = false;
  } line_set;

  // Playback (ui/panels/timeline_panel.h): the shell advances the frame while it is on, and
  // holds it while the timeline's frame is dragged.
  bool playing = false;
  bool scrubbing = false;
  // Scripted runs: parameter widgets report where they are too (ui/widgets/widget_report.h),
  // so a script can point at them.
  bool report_params = false;

  // The document as the viewport shows it: at its current frame. Panels draw and
  // start their edits from it, so an animated parameter shows (and is edited at)
  // the value it has there; edits still go to the document (Document::edit keys them).
  const SceneDesc& shown() {
    const SceneDesc& scene = document.scene();
    if (scene.animation.empty()) return scene;
    if (shown_revision_ != document.revision()) {
      shown_ = scene_at_frame(scene, scene.render.frame);
      shown_revision_ = document.revision();
    }
    return shown_;
  }

  // Edits go through the document so they can be undone.
  void edit(SceneDesc after, std::string label, std::string merge_key = {}) {
    document.edit(std::move(after), std::move(label), std::move(merge_key), selection);
  }
  // A structural edit (add, delete, drop, relink) that is refused, with the reasons in
  // the log, when it would leave the scene with problems it did not have. Problems are
  // counted, not matched: deleting an item renumbers the JSON paths of those after it.
  // *why (when given) gets the reasons too.
  bool edit_checked(SceneDesc after, const std::string& label, std::string* why = nullptr) {
    if (scene_problems(after).size() > scene_problems(document.scene()).size()) {
      std::vector<std::string> added = problems_added(document.scene(), after);
      if (added.empty()) added.push_back("the scene would not render");
      for (const std::string& problem : added) {
        log.warning("cannot " + label + ": " + problem);
        if (why) *why += (why->empty() ? "" : "\n") + problem;
      }
      return false;
    }
    edit(std::move(after), label);
    return true;
  }

 private:
  SceneDesc shown_;
  uint64_t shown_revision_ = 0;
};

}  // namespace inkray
