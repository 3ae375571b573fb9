// A rectangle of pixels: a crop, a tile, a slice of a farm render. Below the film so
// the line sampler and the renderers can speak of pixels without the film.
#pragma once

namespace inkray {

// A pixel window [x0,x1) x [y0,y1); empty means none.
struct PixelWindow {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  bool operator==(const PixelWindow&) const = default;
};

}  // namespace inkray
