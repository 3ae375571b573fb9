// The paint each stroke carries: the object's material colour at the stroke's
// root, jittered in hue, saturation and value.
#pragma once

#include "core/materials/material.h"
#include "core/math/transform.h"
#include "core/npr/strokes/surface_point.h"
#include "core/document/npr_desc.h"

#include <span>
#include <vector>

namespace inkray {

// material indexes materials; a mix is resolved per stroke (so a 50/50 mix
// paints half the strokes in each colour). The jitter is applied to the colour
// as displayed (sRGB-encoded), where equal steps look equal, and is drawn from
// (emitter seed, stroke index).
// `to_object` takes a root into the object's own space, where graph textures are fixed.
std::vector<Color> stroke_colors(std::span<const Material> materials, uint32_t material,
                                 std::span<const SurfacePoint> roots, const StrokeEmitterDesc& emitter,
                                 const Transform& to_object = {});

// The root colour of one stroke before jitter.
Color root_color(std::span<const Material> materials, uint32_t material, const SurfacePoint& root,
                 float mix_u, const Transform& to_object = {});

}  // namespace inkray
