// The film: per-pixel running sums of radiance in two half-buffers (each pass
// adds to one, half_of_pass; their difference estimates the noise without a
// reference, and the denoiser cross-validates its filters on them), and
// the first-hit AOVs a render asked for. Tiles are disjoint, so writers need
// no locks; a pixel is written by one thread at a time.
//
// Sums are kept in double: adding float samples to a double is exact for the
// sums of a render, so a film's sums do not depend on how its passes were split
// between machines and merged again (docs/final-renders.md, "Exactness").
#pragma once

#include "core/image/rgb_image.h"
#include "core/math/hash.h"
#include "core/math/pixel_window.h"
#include "core/integrator/first_hit.h"
#include "core/world/line_types.h"

#include <array>
#include <atomic>
#include <optional>
#include <string_view>
#include <vector>

namespace inkray {

// First-hit AOVs, then the outline coverage: all types together, then one per
// type in LineType order (debug views).
enum class Aov {
  albedo,
  normal,
  depth,
  object_id,
  material_id,
  toon_band,
  outline,
  outline_depth,
  outline_crease,
  outline_intersection,
  outline_material,
  outline_object,
  outline_silhouette
};
inline constexpr std::array<std::string_view, 13> kAovNames = {"albedo",
                                                               "normal",
                                                               "depth",
                                                               "object_id",
                                                               "material_id",
                                                               "toon_band",
                                                               "outline",
                                                               "outline_depth",
                                                               "outline_crease",
                                                               "outline_intersection",
                                                               "outline_material",
                                                               "outline_object",
                                                               "outline_silhouette"};
std::optional<Aov> aov_from_name(std::string_view name);
inline bool is_outline_aov(Aov a) { return uint32_t(a) >= uint32_t(Aov::outline); }
// "albedo, normal, ..." for help texts and error messages.
std::string aov_name_list();

// Which AOVs to keep: the integrator records nothing for the others. Outline
// AOVs read the outline buffers, which exist whenever the scene draws lines.
struct AovSet {
  uint32_t bits = 0;
  bool has(Aov a) const { return bits & (1u << uint32_t(a)); }
  void add(Aov a) { bits |= 1u << uint32_t(a); }
  bool any_first_hit() const { return bits & ((1u << uint32_t(Aov::outline)) - 1u); }
  // AOVs that are averaged over the samples that hit something.
  bool averages_hits() const {
    return has(Aov::albedo) || has(Aov::normal) || has(Aov::depth) || has(Aov::toon_band);
  }
  AovSet first_hit() const { return {bits & ((1u << uint32_t(Aov::outline)) - 1u)}; }
};

// The outline buffers' sums of LineSample, in double like the radiance.
struct LineSums {
  std::array<double, kLineTypeCount> coverage{};
  double weight = 0.0, override_weight = 0.0;
  glm::dvec3 override_color{0.0};
  double rays = 0.0, hit_rays = 0.0;
  void add(const LineSample& s);
  void add(const LineSums& s);
  LineSample mean() const;  // per ray; zero without rays
};

// One pixel's raw state: what a partial file holds and a merge adds up
// (film_partial.h). Ids are -2 before the pixel's first sample.
struct FilmPixel {
  std::array<glm::dvec3, 2> sum{glm::dvec3(0.0),
                                glm::dvec3(0.0)};  // radiance of the two halves (half_of_pass)
  std::array<uint32_t, 2> count{};
  glm::dvec3 albedo_sum{0.0}, normal_sum{0.0};
  double depth_sum = 0.0, band_sum = 0.0;
  uint32_t hit_count = 0;
  int object_id = -2, material_id = -2;
  // Bit 0: samples of the pixel saw more than one object; bit 1: more than one material
  // (an anti-aliased edge: the ids above are only its first sample's).
  uint32_t ids_mixed = 0;
  LineSums lines;
  uint32_t line_count = 0;
};

// The half-buffer a pass adds to. Passes 2k and 2k+1 are a stratified pair of the
// Owen-scrambled Sobol set: one falls in each half of the pixel, the same half for
// every k. Split by parity, the halves would differ at every edge for ever, and the
// noise estimate would never fall there; so each pair's members go to the halves in
// an order hashed from k. Each half still takes one pass of every pair, so the halves
// are equal after an even number of passes.
inline uint32_t half_of_pass(uint32_t pass) { return (pass ^ hash_u32(pass >> 1)) & 1u; }

class Film {
 public:
  // `lines`: keep outline coverage (the scene draws lines).
  Film(int width, int height, AovSet aovs, bool lines = false);

  int width() const { return width_; }
  int height() const { return height_; }
  const AovSet& aovs() const { return aovs_; }
  bool has_lines() const { return !line_sum_.empty(); }

  // `pass` selects the half-buffer. Non-finite values are counted and dropped.
  void add_sample(int x, int y, uint32_t pass, const Color& radiance);
  void add_first_hit(int x, int y, const FirstHit& hit);
  void add_lines(int x, int y, const LineSample& lines);
  void clear();
  // Clears the pixels in [x0,x1) x [y0,y1) only (a render region restarting).
  void clear_region(int x0, int y0, int x1, int y1);

  // A pixel's raw state, of the buffers this film keeps (the others read as empty).
  FilmPixel pixel(int x, int y) const;
  // Adds another film's pixel, from passes after this one's: sums and counts add, ids
  // stay those of the earlier first sample. Buffers this film does not keep are skipped.
  void add_pixel(int x, int y, const FilmPixel& p);
  void add_nonfinite(uint64_t n) { nonfinite_.fetch_add(n, std::memory_order_relaxed); }

  uint64_t nonfinite_samples() const { return nonfinite_.load(std::memory_order_relaxed); }
  uint32_t samples_at(int x, int y) const;
  // Samples in half-buffer `half` (0 even, 1 odd) of a pixel, and their mean luminance
  // (0 without samples): what noise estimates read, without copying the pixel.
  uint32_t half_count(int x, int y, int half) const { return count_[size_t(half)][index(x, y)]; }
  double half_luminance(int x, int y, int half) const;

  // Mean radiance per pixel.
  RgbImage resolve() const;
  // One pixel's mean radiance (black without samples).
  Color mean_radiance(int x, int y) const;
  // The surface a pixel's samples saw first, as far as the film keeps it: mean camera
  // distance of the hits (0: none, or no depth kept), and the ids of its first sample
  // (-1: nothing hit, or not kept). What chains are labelled with (film_chains.h).
  struct Surface {
    float depth = 0.f;
    int object = -1, material = -1;
  };
  Surface surface(int x, int y) const;
  // AOV image: averages for albedo/normal/depth, ids as floats (-1 where nothing
  // was hit), line opacities in [0, 1] for the outline AOVs.
  RgbImage resolve_aov(Aov aov) const;
  // Mean outline contribution of a pixel's stencil rays (zero without lines).
  LineSample line_mean(int x, int y) const;
  // The sums behind it, and the samples that added to them.
  const LineSums& line_sum(int x, int y) const { return line_sum_[index(x, y)]; }
  uint32_t line_samples(int x, int y) const { return line_count_[index(x, y)]; }
  // Estimated relative RMS error of the mean image from the half-buffer
  // difference: sqrt(mean((a-b)^2)/4) / mean(luminance), over luminance.
  double estimated_relative_error() const;
  // Per-pixel relative standard error of the mean, |a - b| / 2 / mean over the
  // luminance of the two half-buffer means a and b, as grey; 0 where a half is
  // empty or the pixel is black (nothing to be relative to).
  RgbImage resolve_noise() const;

 private:
  size_t index(int x, int y) const { return size_t(y) * size_t(width_) + size_t(x); }

  int width_, height_;
  AovSet aovs_;
  std::array<std::vector<glm::dvec3>, 2> sum_;
  std::array<std::vector<uint32_t>, 2> count_;
  std::vector<glm::dvec3> albedo_sum_, normal_sum_;
  std::vector<double> depth_sum_, band_sum_;
  std::vector<uint32_t> hit_count_;
  std::vector<int> object_id_, material_id_;
  std::vector<uint8_t> ids_mixed_;  // FilmPixel::ids_mixed; kept with either id
  std::vector<LineSums> line_sum_;
  std::vector<uint32_t> line_count_;  // samples that added to line_sum_
  std::atomic<uint64_t> nonfinite_{0};
};

}  // namespace inkray
