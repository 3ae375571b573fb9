// The one way the editor makes a GL texture for an image it shows (the viewport, the
// material swatches, the image view): RGBA8, clamped at the edges, linear when shrunk.
#pragma once

namespace inkray {

enum class Magnify { smooth, pixels };  // pixels: nearest, for inspecting an image at 1:1 and beyond

unsigned make_image_texture(Magnify magnify = Magnify::smooth);

}  // namespace inkray
