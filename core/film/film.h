// The film: per-pixel running sums of radiance in two half-buffers (even and
// odd passes, whose difference estimates the noise without a reference), and
// the first-hit AOVs a render asked for. Tiles are disjoint, so writers need
// no locks; a pixel is written by one thread at a time.
#pragma once

#include "core/image/rgb_image.h"

#include <array>
#include <atomic>
#include <optional>
#include <string_view>
#include <vector>

namespace inkray {

enum class Aov { albedo, normal, depth, object_id, material_id };
inline constexpr std::array<std::string_view, 5> kAovNames = {"albedo", "normal", "depth", "object_id",
                                                                "material_id"};
std::optional<Aov> aov_from_name(std::string_view name);

// Which AOVs to keep: the integrator records nothing for the others.
struct AovSet {
  uint32_t bits = 0;
  bool has(Aov a) const { return bits & (1u << uint32_t(a)); }
  void add(Aov a) { bits |= 1u << uint32_t(a); }
  bool any() const { return bits != 0; }
};

// What the camera sample saw at its first hit.
struct FirstHit {
  Color albedo{0.f};
  Normal3 normal{0.f};
  float depth = 0.f;  // distance along the camera's forward axis
  int object = -1;    // -1 where the sample escaped
  int material = -1;
};

class Film {
 public:
  Film(int width, int height, AovSet aovs);

  int width() const { return width_; }
  int height() const { return height_; }
  const AovSet& aovs() const { return aovs_; }

  // `pass` selects the half-buffer. Non-finite values are counted and dropped.
  void add_sample(int x, int y, uint32_t pass, const Color& radiance);
  void add_first_hit(int x, int y, const FirstHit& hit);
  void clear();

  uint64_t nonfinite_samples() const { return nonfinite_.load(std::memory_order_relaxed); }
  uint32_t samples_at(int x, int y) const;

  // Mean radiance per pixel.
  RgbImage resolve() const;
  // AOV image: averages for albedo/normal/depth, ids as floats (-1 where nothing was hit).
  RgbImage resolve_aov(Aov aov) const;
  // Estimated relative RMS error of the mean image from the half-buffer
  // difference: sqrt(mean((a-b)^2)/4) / mean(luminance), over luminance.
  double estimated_relative_error() const;

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
  std::atomic<uint64_t> nonfinite_{0};
};

}  // namespace inkray
