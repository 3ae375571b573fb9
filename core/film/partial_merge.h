// Merging partial renders (film_partial.h): whether partials come from one render,
// and adding them up to its film, refusing what would not be that film.
#pragma once

#include "core/film/film_partial.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace inkray {

// Whether two partials come from the same render: image size, frame, seed, AOVs,
// the scene (its sample limits aside) and the bytes of its assets. "" when they do,
// else what differs, e.g. "seed 1 vs 2", "the scene differs at render/max_depth: 8 vs
// 16" or "the asset meshes/bunny.obj changed between them (...)".
std::string partial_mismatch(const PartialInfo& a, const PartialInfo& b);

// Adds partials into one film of the full image, checking that they can be
// merged: every pair is compatible (partial_mismatch), no pixel holds a pass
// twice and each pixel's passes are one unbroken range. `whole`: every pixel
// must be covered, from pass 0 (a final image); otherwise the pixels covered
// must form one window with one range (a partial again). Files are read one at
// a time, in the order of their first pass, so sums add up in the order a single
// render adds them.
struct MergedFilm {
  std::unique_ptr<Film> film;                 // the full image
  PartialInfo info;                           // the merged range and window; the first file's scene
  uint32_t min_samples = 0, max_samples = 0;  // samples per covered pixel
};
bool merge_partials(const std::vector<std::filesystem::path>& files, bool whole, MergedFilm* merged,
                    std::string* error);

}  // namespace inkray
