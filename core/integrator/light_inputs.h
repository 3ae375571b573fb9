// The light inputs of material graphs (light_input node): the strongest light at
// a hit, how it falls on the surface, and whether it is seen. Gathered only for
// graphs that read them, with one shadow ray.
#pragma once

#include "core/materials/shading_point.h"
#include "core/world/render_scene.h"

namespace inkray {

// Fills sp's light inputs. The strongest light is the one whose unshadowed radiance
// (sampled at the centre of area lights) has the largest luminance; *rays counts
// the shadow ray, traced at shutter instant `time`. Without lights: n_dot_l 0,
// shadow 0, colour black.
void gather_light_inputs(const RenderScene& scene, const LightReference& ref, float time, ShadingPoint& sp,
                         uint32_t* rays);

}  // namespace inkray
