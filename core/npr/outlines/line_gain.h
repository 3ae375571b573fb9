// The gain that turns a pixel's mean stencil coverage into line opacity
// without making lines heavier in coarse images (docs/outlines.md, "Coverage,
// width and resolution").
//
// A pixel's opacity is min(1, gain * mean coverage). Where pixels are much
// smaller than the stencil, gain kLineGain draws the intended profile: solid
// within 0.40 r of an edge, fading out at r. Where a pixel spans much of the
// stencil, its mean coverage averages that profile's unclamped tail too, and
// the same gain would put about 31% more ink into the pixel than the fine
// image puts into the same area. The gain below keeps the ink of a straight
// edge (the integral of opacity across it) equal to the fine image's for every
// ratio of pixel width to stencil radius, so mean line darkness does not
// depend on resolution.
#pragma once

namespace inkray {

// `pixel_over_radius`: the film pixel's sample footprint width over the
// stencil radius, both in pixels of the full image. Returns a gain in
// (0, kLineGain]: kLineGain for tiny pixels, falling towards about 3 for pixels
// many radii wide.
float ink_preserving_gain(float pixel_over_radius);

}  // namespace inkray
