// The film: per-pixel running sums of radiance in two half-buffers (even and
// odd passes, whose difference estimates the noise without a reference), and
// the first-hit AOVs a render asked for. Tiles are disjoint, so writers need
// no locks; a pixel is written by one thread at a time.
#pragma once

#include "core/image/rgb_image.h"
#include "core/integrator/first_hit.h"
#include "core/npr/outlines/line_types.h"

#include <array>
#include <atomic>
#include <optional>
#include <string_view>
#include <vector>

namespace inkray {

// First-hit AOVs, then the outline coverage: all types together, then one per
// type in LineType order (debug views).
enum class Aov {
  albedo, normal, depth, object_id, material_id,
  outline, outline_depth, outline_crease, outline_intersection, outline_material, outline_object,
  outline_silhouette
};
inline constexpr std::array<std::string_view, 12> kAovNames = {
    "albedo",          "normal",         "depth",
    "object_id",       "material_id",    "outline",
    "outline_depth",   "outline_crease", "outline_intersection",
    "outline_material", "outline_object", "outline_silhouette"};
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
};

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

  uint64_t nonfinite_samples() const { return nonfinite_.load(std::memory_order_relaxed); }
  uint32_t samples_at(int x, int y) const;

  // Mean radiance per pixel.
  RgbImage resolve() const;
  // AOV image: averages for albedo/normal/depth, ids as floats (-1 where nothing
  // was hit), line opacities in [0, 1] for the outline AOVs.
  RgbImage resolve_aov(Aov aov) const;
  // Mean outline contribution of a pixel's stencil rays (zero without lines).
  LineSample line_mean(int x, int y) const;
  // The sums behind it, and the samples that added to them (adaptive line sampling).
  const LineSample& line_sum(int x, int y) const { return line_sum_[index(x, y)]; }
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
  std::array<std::vector<Color>, 2> sum_;
  std::array<std::vector<uint32_t>, 2> count_;
  std::vector<Color> albedo_sum_, normal_sum_;
  std::vector<float> depth_sum_;
  std::vector<uint32_t> hit_count_;
  std::vector<int> object_id_, material_id_;
  std::vector<LineSample> line_sum_;
  std::vector<uint32_t> line_count_;  // samples that added to line_sum_
  std::atomic<uint64_t> nonfinite_{0};
};

}  // namespace inkray
