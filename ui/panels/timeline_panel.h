// The timeline under the viewport (docs/architecture.md, "Timeline and keys"): play,
// pause and step, the current frame, the shot's range and frame rate, and a scrub bar
// with numbered frames and the keys: every key of the scene in one row, the selected
// item's in the row below. The frame moves without undo steps (Document::set_frame);
// range and rate are ordinary edits.
#pragma once

#include "ui/model/editor_state.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace inkray {

// Playback by the wall clock: the frame shown is the one the clock has reached since
// play began, so a frame that renders slowly is skipped rather than making the whole
// playback late. Plays to frame_end, then loops from frame_start. Window-free.
class PlaybackClock {
 public:
  using Clock = std::chrono::steady_clock;

  // Counts from `frame` at `now` (at play, and again whenever the frame is moved by hand).
  void start(double frame, Clock::time_point now) {
    from_ = frame;
    started_ = now;
  }
  // A whole frame in [frame_start, frame_end]; a start outside the range starts at frame_start.
  double frame_at(Clock::time_point now, const RenderSettings& r) const {
    const double first = r.frame_start, last = std::max(r.frame_end, r.frame_start);
    double from = std::floor(from_);
    if (from < first || from > last) from = first;
    const double elapsed = std::max(std::chrono::duration<double>(now - started_).count(), 0.0);
    const double frames = std::floor(elapsed * std::max(double(r.fps), 1e-3));
    return first + std::fmod(from - first + frames, last - first + 1.0);
  }

 private:
  double from_ = 1.0;
  Clock::time_point started_;
};

// What the transport buttons and their shortcuts do (the shell binds the keys).
void toggle_playback(EditorState& state);
void step_frame(EditorState& state, int frames);      // from the whole frame nearest
void jump_to_end(EditorState& state, bool last);      // frame_start, or frame_end
void jump_to_key(EditorState& state, int direction);  // the next (+1) or previous (-1) frame with a key

void draw_timeline_panel(EditorState& state);

}  // namespace inkray
