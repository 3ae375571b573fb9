// Adaptive line sampling: how many stencil rays the next sample of a pixel
// traces, from what the pixel's first stencil rays saw. Most pixels hold no
// line and stop needing rays after a few samples; pixels inside a solid line
// have converged; pixels on a line's soft edge keep going, with more rays the
// wider the line (docs/outlines.md, "Cost").
//
// Every stencil ray is an unbiased estimate of its pixel's coverage whatever
// the count, and the film averages over rays, so the converged lines are those
// of full sampling. Skipped samples are chosen by a hash, not by pass number:
// a regular subset of a Sobol sequence's camera points would cover one part
// of the pixel only.
//
// Decisions are made early and then kept: the map of pixels near a line comes
// from the probes alone, and a pixel near a line decides what it is once its
// own rays are enough to tell. So what any later pass traces follows from the
// first few passes of a pixel and its neighbours, which a render of a later
// slice of passes or of a crop window traces again (docs/final-renders.md):
// it then traces exactly what a render of every pass would have.
#pragma once

#include "core/math/pixel_window.h"
#include "core/npr/outlines/line_detector.h"
#include "core/world/line_types.h"

#include <cstdint>
#include <vector>

namespace inkray {

// Samples every pixel traces at `quality` rays before any decision.
inline constexpr uint32_t kLineProbeSamples = 4;

enum class LineKind : uint8_t {
  probing,  // the first kLineProbeSamples samples
  quiet,    // no break seen within the stencil's reach during the probes
  finding,  // near a line, too few rays of its own to tell more yet
  beside,   // near a line, its own rays saw none
  solid,    // inside a solid line
  edge,     // on a line's soft edge
};

// What line sampling knows of one film pixel.
struct LinePixel {
  uint32_t rays = 0;  // stencil rays traced so far: the next one's index in the pixel's sequence
  LineKind kind = LineKind::probing;
  // The pixel's rays until it decided (probing and finding): what the decision reads.
  float hit_rays = 0.f, weight = 0.f;
  std::array<float, kLineTypeCount> coverage{};
};

// What line sampling decided for every pixel of a film, at the first pass
// `decided_at` (at or after the probes) before which no pixel is still deciding:
// from there on a pixel's samples follow from its kind and ray count alone
// (stencil_rays_between), so a render that starts at or after `decided_at` needs
// nothing else of the passes before it. Made once for a split render and read by
// its slices instead of each tracing the decisions again (docs/final-renders.md,
// "Line decisions").
struct LineDecisions {
  int width = 0, height = 0;  // of the film; no pixels when the scene draws no lines
  uint32_t decided_at = 0;
  std::vector<uint32_t> rays;  // per pixel, row by row: LinePixel::rays at decided_at
  std::vector<LineKind> kinds;
  bool operator==(const LineDecisions&) const = default;
};

// Film pixels a stencil reaches: a pixel's kind depends on the probes of the
// pixels this close to it.
int line_reach(const LineSetup& setup);

// Which pixels are near a line: those within the stencil's reach of a pixel
// whose probes have seen a break. A pixel is quiet only when its whole
// neighbourhood is, so a line found by the pixels beside it is not left to a
// pixel's own few probes. Made once, after the last probe pass, from the
// probes of every pixel (each thread count decides alike); sets the kind of the
// pixels in `window` that are still probing.
void mark_line_neighbourhoods(std::vector<LinePixel>& pixels, int width, int height, const LineSetup& setup,
                              const PixelWindow& window);

// The ray count for the pixel's sample of `pass` (0: no line work at all);
// decides the pixel's kind when its rays are enough. `pass` and `seed` pick
// the samples that still probe quiet pixels.
int stencil_rays(const LineSetup& setup, LinePixel& pixel, uint32_t x, uint32_t y, uint32_t pass,
                 uint32_t seed);

// The rays of the pixel's samples of passes [first, end), all at or after the
// probes, counted without deciding anything: for a pixel that has decided (or
// whose sampling is not adaptive), what `rays` becomes after those passes.
uint32_t stencil_rays_between(const LineSetup& setup, const LinePixel& pixel, uint32_t x, uint32_t y,
                              uint32_t first, uint32_t end, uint32_t seed);

// Whether a decision still reads this pixel's rays: only then must a sample be
// traced to know what comes after it (otherwise its count is enough).
inline bool line_decision_pending(const LineSetup& setup, const LinePixel& pixel) {
  return setup.adaptive && (pixel.kind == LineKind::probing || pixel.kind == LineKind::finding);
}

// Adds a sample's stencil results to what the pixel knows.
void record_line_sample(const LineSetup& setup, LinePixel& pixel, const LineSample& sample);

}  // namespace inkray
