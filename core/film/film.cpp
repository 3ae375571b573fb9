#include "core/film/film.h"

#include <algorithm>

#include <cmath>

namespace inkray {

std::optional<Aov> aov_from_name(std::string_view name) {
  for (size_t i = 0; i < kAovNames.size(); ++i)
    if (kAovNames[i] == name) return Aov(i);
  return std::nullopt;
}

std::string aov_name_list() {
  std::string list;
  for (const std::string_view name : kAovNames) {
    if (!list.empty()) list += ", ";
    list += name;
  }
  return list;
}

Film::Film(int width, int height, AovSet aovs, bool lines) : width_(width), height_(height), aovs_(aovs) {
  const size_t n = size_t(width) * size_t(height);
  for (int h = 0; h < 2; ++h) {
    sum_[h].assign(n, Color(0.f));
    count_[h].assign(n, 0);
  }
  // Pay only for what is asked for: a render keeps only the AOVs it was asked for.
  if (aovs.has(Aov::albedo)) albedo_sum_.assign(n, Color(0.f));
  if (aovs.has(Aov::normal)) normal_sum_.assign(n, Color(0.f));
  if (aovs.has(Aov::depth)) depth_sum_.assign(n, 0.f);
  if (aovs.has(Aov::albedo) || aovs.has(Aov::normal) || aovs.has(Aov::depth)) hit_count_.assign(n, 0);
  if (aovs.has(Aov::object_id)) object_id_.assign(n, -2);
  if (aovs.has(Aov::material_id)) material_id_.assign(n, -2);
  if (lines) {
    line_sum_.assign(n, LineSample{});
    line_count_.assign(n, 0);
  }
}

void Film::clear() {
  Film fresh(width_, height_, aovs_, has_lines());
  sum_ = std::move(fresh.sum_);
  count_ = std::move(fresh.count_);
  albedo_sum_ = std::move(fresh.albedo_sum_);
  normal_sum_ = std::move(fresh.normal_sum_);
  depth_sum_ = std::move(fresh.depth_sum_);
  hit_count_ = std::move(fresh.hit_count_);
  object_id_ = std::move(fresh.object_id_);
  material_id_ = std::move(fresh.material_id_);
  line_sum_ = std::move(fresh.line_sum_);
  line_count_ = std::move(fresh.line_count_);
  nonfinite_ = 0;
}

void Film::clear_region(int x0, int y0, int x1, int y1) {
  for (int y = std::max(y0, 0); y < std::min(y1, height_); ++y) {
    for (int x = std::max(x0, 0); x < std::min(x1, width_); ++x) {
      const size_t i = index(x, y);
      for (int half = 0; half < 2; ++half) {
        sum_[size_t(half)][i] = Color(0.f);
        count_[size_t(half)][i] = 0;
      }
      if (!albedo_sum_.empty()) albedo_sum_[i] = Color(0.f);
      if (!normal_sum_.empty()) normal_sum_[i] = Color(0.f);
      if (!depth_sum_.empty()) depth_sum_[i] = 0.f;
      if (!hit_count_.empty()) hit_count_[i] = 0;
      if (!object_id_.empty()) object_id_[i] = -2;
      if (!material_id_.empty()) material_id_[i] = -2;
      if (!line_sum_.empty()) {
        line_sum_[i] = LineSample{};
        line_count_[i] = 0;
      }
    }
  }
}

void Film::add_sample(int x, int y, uint32_t pass, const Color& radiance) {
  const size_t i = index(x, y);
  if (!is_finite(radiance)) {
    nonfinite_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  const uint32_t half = pass & 1u;
  ++count_[half][i];
  sum_[half][i] += radiance;
}

void Film::add_first_hit(int x, int y, const FirstHit& hit) {
  const size_t i = index(x, y);
  // Ids are not averaged: the first sample's id stands for the pixel.
  if (!object_id_.empty() && object_id_[i] == -2) object_id_[i] = hit.object;
  if (!material_id_.empty() && material_id_[i] == -2) material_id_[i] = hit.material;
  if (hit_count_.empty() || hit.object < 0) return;
  ++hit_count_[i];
  if (!albedo_sum_.empty()) albedo_sum_[i] += hit.albedo;
  if (!normal_sum_.empty()) normal_sum_[i] += hit.normal;
  if (!depth_sum_.empty()) depth_sum_[i] += hit.depth;
}

void Film::add_lines(int x, int y, const LineSample& lines) {
  const size_t i = index(x, y);
  LineSample& sum = line_sum_[i];
  for (size_t t = 0; t < sum.coverage.size(); ++t) sum.coverage[t] += lines.coverage[t];
  sum.weight += lines.weight;
  sum.override_weight += lines.override_weight;
  sum.override_color += lines.override_color;
  sum.rays += lines.rays;
  sum.hit_rays += lines.hit_rays;
  ++line_count_[i];
}

LineSample Film::line_mean(int x, int y) const {
  if (line_sum_.empty()) return {};
  const size_t i = index(x, y);
  if (!(line_sum_[i].rays > 0.f)) return {};
  LineSample mean = line_sum_[i];
  const float inv = 1.f / line_sum_[i].rays;
  for (float& c : mean.coverage) c *= inv;
  mean.weight *= inv;
  mean.override_weight *= inv;
  mean.override_color *= inv;
  return mean;
}

uint32_t Film::samples_at(int x, int y) const { return count_[0][index(x, y)] + count_[1][index(x, y)]; }

RgbImage Film::resolve() const {
  RgbImage img{width_, height_, std::vector<Color>(size_t(width_) * size_t(height_), Color(0.f))};
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const uint32_t n = count_[0][i] + count_[1][i];
    if (n) img.pixels[i] = (sum_[0][i] + sum_[1][i]) / float(n);
  }
  return img;
}

RgbImage Film::resolve_aov(Aov aov) const {
  RgbImage img{width_, height_, std::vector<Color>(size_t(width_) * size_t(height_), Color(0.f))};
  if (is_outline_aov(aov)) {
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x) {
        const LineSample m = line_mean(x, y);
        float opacity = 0.f;
        if (aov == Aov::outline) {
          for (const float c : m.coverage) opacity = std::max(opacity, line_opacity(c));
        } else {
          opacity = line_opacity(m.coverage[size_t(aov) - size_t(Aov::outline_depth)]);
        }
        img.pixels[index(x, y)] = Color(opacity);
      }
    return img;
  }
  if (!aovs_.has(aov)) return img;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const float hits = hit_count_.empty() ? 0.f : float(hit_count_[i]);
    switch (aov) {
      case Aov::albedo: img.pixels[i] = hits ? albedo_sum_[i] / hits : Color(0.f); break;
      case Aov::normal: {
        const Vec3 n = normal_sum_[i];
        img.pixels[i] = glm::length(n) > 0.f ? glm::normalize(n) : Vec3(0.f);
        break;
      }
      case Aov::depth: img.pixels[i] = Color(hits ? depth_sum_[i] / hits : 0.f); break;
      case Aov::object_id: img.pixels[i] = Color(float(object_id_[i] < -1 ? -1 : object_id_[i])); break;
      case Aov::material_id: img.pixels[i] = Color(float(material_id_[i] < -1 ? -1 : material_id_[i])); break;
      default: break;  // outline AOVs are handled above
    }
  }
  return img;
}

double Film::estimated_relative_error() const {
  double diff2 = 0.0, lum = 0.0;
  size_t pixels = 0;
  for (size_t i = 0; i < sum_[0].size(); ++i) {
    const uint32_t na = count_[0][i], nb = count_[1][i];
    if (!na || !nb) continue;
    const double a = luminance(sum_[0][i]) / na, b = luminance(sum_[1][i]) / nb;
    // Var(mean of both) ~ (a - b)^2 / 4 for equal halves.
    diff2 += (a - b) * (a - b) * 0.25;
    lum += 0.5 * (a + b);
    ++pixels;
  }
  if (!pixels || lum <= 0.0) return 0.0;
  return std::sqrt(diff2 / double(pixels)) / (lum / double(pixels));
}

RgbImage Film::resolve_noise() const {
  RgbImage img{width_, height_, std::vector<Color>(size_t(width_) * size_t(height_), Color(0.f))};
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const uint32_t na = count_[0][i], nb = count_[1][i];
    if (!na || !nb) continue;
    const double a = luminance(sum_[0][i]) / na, b = luminance(sum_[1][i]) / nb;
    const double mean = 0.5 * (a + b);
    if (mean <= 0.0) continue;
    img.pixels[i] = Color(float(std::abs(a - b) * 0.5 / mean));
  }
  return img;
}

}  // namespace inkray
