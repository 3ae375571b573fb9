// Pixel paths of one line type: the pixels of a line thinned to a one-pixel
// skeleton (Zhang and Suen 1984, then the corner pixels of staircases removed),
// traced between ends and crossings, and joined through each crossing into the
// partner that turns the least. The first half of chaining (chain_builder.h).
#pragma once

#include "core/math/types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace inkray {

struct PixelPath {
  std::vector<Vec2> pixels;  // pixel centres in order
  bool closed = false;       // the last pixel neighbours the first
  // Whether the first and the last pixel end in a crossing (one no partner was joined
  // through there): the line goes on, as other paths, where this one stops.
  std::array<bool, 2> ends_at_crossing{false, false};
};

// Reused across line types and images of one size: it keeps its mask, so tracing
// costs what the line pixels do, not the image.
class PixelSkeleton {
 public:
  PixelSkeleton(int width, int height);
  // The paths of the pixels `on` (row-major indices), joined at crossings where the
  // continuation turns by less than join_angle degrees. Single pixels give none.
  std::vector<PixelPath> trace(const std::vector<uint32_t>& on, float join_angle);

 private:
  int neighbours(uint32_t i) const;  // bits N, NE, E, SE, S, SW, W, NW of set neighbours
  void thin(std::vector<uint32_t>& on);
  void remove_staircases(std::vector<uint32_t>& on);

  int width_, height_;
  std::vector<uint8_t> mask_;  // 1: skeleton pixel
};

}  // namespace inkray
