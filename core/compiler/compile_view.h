// The document's render settings and outlines -> the view's compiled settings
// (core/world/view_settings.h). Also what a merge or a render time estimate uses
// to resolve a film without compiling a scene.
#pragma once

#include "core/document/desc.h"
#include "core/world/view_settings.h"

namespace inkray {

SampleSettings compile_sample_settings(const RenderSettings& render);
ResolveSettings compile_resolve_settings(const RenderSettings& render, const OutlineDesc& outlines);

}  // namespace inkray
