#include "core/render/batch_render.h"

namespace inkray {

std::vector<PassRecord> render_batch(RenderSession& session, const BatchLimits& limits,
                                     const std::function<void(const RenderStats&)>& on_pass) {
  std::vector<PassRecord> history;
  while (int(session.stats().spp) < limits.spp) {
    if (!session.render_pass()) break;
    const RenderStats& s = session.stats();
    history.push_back({s.passes, s.spp, s.elapsed_seconds, s.relative_error});
    if (on_pass) on_pass(s);
    // The time limit is checked between passes, so a pass in flight finishes.
    if (limits.time_seconds > 0.0 && s.elapsed_seconds >= limits.time_seconds) break;
  }
  return history;
}

}  // namespace inkray
