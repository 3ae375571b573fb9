// Sampling lights from a receiving point, and the solid-angle density of
// reaching a light by other means (for multiple importance sampling).
#pragma once

#include "core/lights/light.h"
#include "core/world/world.h"

namespace inkray {

std::optional<LightSample> sample_light(const World& world, const Light& light, const LightReference& ref,
                                        Vec2 u);
// Solid-angle pdf that sample_light would produce direction wi hitting `on_light`
// (ignored for the environment). Zero for delta lights.
float light_pdf(const World& world, const Light& light, const LightReference& ref, const Vec3& wi,
                const SurfaceInteraction& on_light);
// Estimated emitted power (luminance), the weight for choosing among lights.
float light_power(const World& world, const Light& light);

}  // namespace inkray
