// What the editor does beyond an artist's session, for tests and measurements: select an
// object or open the node editor at start, drop files, export through the dialog, write
// a screenshot with its reports, measure edits, stop after a number of frames. main()
// calls one hook before and one after each frame (docs/architecture.md, "Testing the
// editor"); without any of these options the hooks do nothing.
#pragma once

#include "app/edit_measurement.h"
#include "ui/editor_app.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace inkray {

struct ScriptOptions {
  std::string screenshot;  // write the window here (PNG) once the viewport is full size, then exit
  int frames = 0;          // frames to run first (with no screenshot: then exit); 0: until closed
  int measure_edits = 0;   // edits of each kind to measure; 0: no measurement
  std::vector<measure::EditKind> edit_kinds;  // empty: camera
  std::string select;                         // object to select at start, so screenshots show the highlight
  std::string node_material;                  // material to open the node editor on
  std::string node_layout;                    // where to write the node editor's layout with the screenshot
  std::string widget_report;       // where to write the named widgets' rectangles with the screenshot
  std::vector<std::string> drops;  // files handed to the editor as dropped after the first frame
  std::string scene_dump;          // where to write the document (JSON) with the screenshot
  std::string export_path;         // export through the dialog to this file, then take the screenshot

  // An interactive session: no option above is set.
  bool interactive() const { return screenshot.empty() && measure_edits == 0; }
};

class ScriptedRun {
 public:
  explicit ScriptedRun(ScriptOptions options);
  ~ScriptedRun();

  // Before the first frame: the selection, the node editor, the kinds of edit to
  // measure. False when the run cannot start (exit_code says why it failed).
  bool start(EditorApp& app);
  // Before each frame is drawn: the files to drop, after the first frame.
  void before_frame(EditorApp& app, int frame);
  // After each frame is drawn, before it is presented: the export, the screenshot and
  // its reports, the next measured edit, the frame limit. False: stop the loop.
  bool after_frame(EditorApp& app, int frame, int width, int height, double work_ms);

  int exit_code() const { return exit_code_; }

 private:
  bool track_export(EditorApp& app, int frame);
  bool write_outputs(EditorApp& app, int width, int height);

  ScriptOptions opt_;
  int exit_code_ = 0;
  std::unique_ptr<measure::EditMeasurement> measurement_;
  bool kind_skipped_ = false;  // a kind this scene cannot take: measure the rest, then fail
  uint64_t export_id_ = 0;
  int export_finished_frame_ = -1;  // the screenshot waits a few frames more: the image view opens
  double started_ = 0.0;            // seconds on the steady clock at start()
};

}  // namespace inkray
