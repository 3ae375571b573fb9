// Hidden lines: the silhouettes and creases of the scene's surfaces where one or more
// surfaces stand between them and the camera (a technical drawing's dashed edges,
// Freestyle's quantitative invisibility), as chains like those traced from the film
// (chain.h) with `covers` counting those surfaces. They are found on the geometry
// (surface_edges.h), not in the image, and checked by rays from the camera at the
// frame, a pinhole (depth of field and motion blur set aside).
#pragma once

#include "core/base/cancel.h"
#include "core/world/chain.h"
#include "core/world/render_scene.h"

#include <vector>

namespace inkray {

// The hidden chains of the line types scene.lines enables (silhouette and crease), in
// pixels of the full image (scene.sampling.width x height, y down) and clipped to it,
// in LineType order, each started and run as orient_chain (chain_shape.h) has it.
// A chain's covers is the same all along it: where the count changes, chains end.
// Empty once `cancel` is requested.
std::vector<Chain> hidden_chains(const RenderScene& scene, const Cancel& cancel = {});

}  // namespace inkray
