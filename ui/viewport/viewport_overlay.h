// What the viewport draws over its image: the statistics (samples, passes, time, rays
// per second, the error estimate and its plot against time, with labelled axes) and,
// when the newest document cannot render, the reasons. Sizes follow the UI scale.
#pragma once

#include "core/render/progressive_renderer.h"

#include <string>
#include <vector>

namespace inkray {

// Both at the image's top left corner (x, y), in window pixels.
void draw_stats_overlay(const ViewportSnapshot& snapshot, float x, float y);
void draw_problems_overlay(const std::vector<std::string>& problems, float x, float y, float image_width);

}  // namespace inkray
