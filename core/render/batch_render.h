// A final render: passes until the sample count or the time limit is reached,
// recording error against time after every pass.
#pragma once

#include "core/render/render_session.h"

#include <functional>
#include <vector>

namespace inkray {

struct BatchLimits {
  int spp = 64;
  double time_seconds = 0.0;  // 0 means no limit
};

struct PassRecord {
  uint32_t pass = 0;
  uint32_t spp = 0;
  double elapsed_seconds = 0.0;
  double relative_error = 0.0;
};

// Renders into the session's film; on_pass runs after every completed pass. The time
// limit cuts a pass in flight, the first included: when it cuts the first, some
// pixels have no sample and the history is empty, which callers must not write out.
std::vector<PassRecord> render_batch(RenderSession& session, const BatchLimits& limits,
                                     const std::function<void(const RenderStats&)>& on_pass = {});

}  // namespace inkray
