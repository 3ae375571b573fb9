// The material preview swatch: one material of a document on a sphere over a
// checker floor, lit by a key light, a fill light and a sky, as a document of its
// own. The editor renders it with a ProgressiveRenderer on one thread, so a node
// edit refines its swatch while the viewport keeps the other cores.
#pragma once

#include "core/document/desc.h"

#include <string>

namespace inkray {

// The swatch scene for `material` (a name in `doc`): that material and those it
// refers to (a mix's sides), square, `size` pixels a side, `spp` samples. Asset
// paths resolve against the document's folder. A name not in `doc` gives a scene
// whose sphere uses a missing material, which fails to compile with that name.
SceneDesc material_preview_scene(const SceneDesc& doc, const std::string& material, int size = 128,
                                 int spp = 64);

}  // namespace inkray
