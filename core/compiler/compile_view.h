// The document's render settings and outlines -> the view's compiled settings
// (core/world/view_settings.h). Also what a merge or a render time estimate uses
// to resolve a film without compiling a scene.
#pragma once

#include "core/compiler/compile_line_sets.h"
#include "core/document/desc.h"
#include "core/world/view_settings.h"

namespace inkray {

SampleSettings compile_sample_settings(const RenderSettings& render);
ResolveSettings compile_resolve_settings(const RenderSettings& render, const OutlineDesc& outlines);
// The whole document's, line sets included: what the compiler gives a view, and what a
// merge resolves with. Errors (a brush that cannot be read) go to *errors.
ResolveSettings compile_resolve_settings(const SceneDesc& desc, const LineBrushLoader& brushes,
                                         std::vector<std::string>* errors);

}  // namespace inkray
