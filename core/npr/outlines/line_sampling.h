// Adaptive line sampling: how many stencil rays the next sample of a pixel
// traces, from what the pixel's earlier stencil rays saw. Most pixels hold no
// line and stop needing rays after a few samples; pixels inside a solid line
// have converged; pixels on a line's soft edge keep going, with more rays the
// wider the line (docs/outlines.md, "Cost").
//
// Every stencil ray is an unbiased estimate of its pixel's coverage whatever
// the count, and the film averages over rays, so the converged lines are those
// of full sampling. Skipped samples are chosen by a hash, not by pass number:
// a regular subset of a Sobol sequence's camera points would cover one part
// of the pixel only.
#pragma once

#include "core/film/film.h"
#include "core/npr/outlines/line_detector.h"

#include <cstdint>
#include <vector>

namespace inkray {

// Samples every pixel traces at `quality` rays before any decision.
inline constexpr uint32_t kLineProbeSamples = 4;

// Which pixels are near a line: those within the stencil's reach of a pixel
// whose rays have seen a break. A pixel is quiet only when its whole
// neighbourhood is, so a line found by the pixels beside it is not left to a
// pixel's own few probes. Made from the finished passes between passes, so
// every thread count makes the same decisions. One byte per film pixel.
void mark_line_neighbourhoods(const Film& film, const LineSetup& setup, std::vector<uint8_t>& near_line);

// `sum`: the pixel's stencil results so far (Film::line_sum), `samples`: the
// samples they came from, `near_line`: its entry of mark_line_neighbourhoods;
// `pass` and `seed` pick the samples that still probe quiet pixels. Returns the
// ray count for this sample (0: no line work at all).
int stencil_rays(const LineSetup& setup, const LineSample& sum, uint32_t samples, bool near_line, uint32_t x,
                 uint32_t y, uint32_t pass, uint32_t seed);

}  // namespace inkray
