// Turns a linear image into the 8-bit RGBA a viewport shows: exposure and a
// view transform, then an outline around a highlighted object. Done off the UI
// thread so display changes never need a re-render and never stall a frame.
#pragma once

#include "core/image/rgb_image.h"
#include "core/image/view_transform.h"

#include <array>
#include <cstdint>
#include <vector>

namespace inkray {

// 4 bytes per pixel, row 0 at the top, alpha 255: the display-linear values of
// DisplayMapping, sRGB-encoded, but for raw, whose values are written as they are.
std::vector<uint8_t> encode_display(const RgbImage& image, const DisplayEncoding& encoding);

// Paints the inner border, `thickness` pixels wide, of the pixels whose id
// equals `object` (ids as stored in the object_id AOV) in `rgb`, and the one-pixel
// ring just outside it in `rim`, so a selection stays visible over any image and
// reads apart from any outline, which is one colour. A full-resolution film is
// usually shown a little scaled, where a 1-pixel line blends into its neighbours:
// use 2 there.
void paint_highlight(std::vector<uint8_t>& rgba, const RgbImage& object_ids, int object,
                     std::array<uint8_t, 3> rgb, int thickness = 1, std::array<uint8_t, 3> rim = {24, 14, 0});

}  // namespace inkray
