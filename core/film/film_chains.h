// A film's lines as chains (docs/architecture.md, "Lines as strokes"): its mean
// line coverage per type, thinned and traced by core/npr/lines/chain_builder.h,
// each point labelled with the first-hit surface the film kept there.
#pragma once

#include "core/film/film.h"
#include "core/world/chain.h"

#include <cstdint>
#include <vector>

namespace inkray {

// The first-hit layers chains are labelled from: a film whose scene has line sets keeps them.
AovSet chain_aovs();

// The chains of `film`'s lines. `material_paths` says, by material index, whether a
// line seen on that material is seen in a mirror or through glass (LinePath); a
// material beyond it, or a film without ids, counts as direct. Points carry the
// mean radiance's luminance under them as their light, clamped to 1.
std::vector<Chain> film_chains(const Film& film, const std::vector<uint8_t>& material_paths);

}  // namespace inkray
