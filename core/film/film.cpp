#include "core/film/film.h"

#include "core/base/parallel.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

double dluminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace

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

void LineSums::add(const LineSample& s) {
  for (size_t t = 0; t < coverage.size(); ++t) coverage[t] += double(s.coverage[t]);
  weight += double(s.weight);
  override_weight += double(s.override_weight);
  override_color += glm::dvec3(s.override_color);
  rays += double(s.rays);
  hit_rays += double(s.hit_rays);
}

void LineSums::add(const LineSums& s) {
  for (size_t t = 0; t < coverage.size(); ++t) coverage[t] += s.coverage[t];
  weight += s.weight;
  override_weight += s.override_weight;
  override_color += s.override_color;
  rays += s.rays;
  hit_rays += s.hit_rays;
}

LineSample LineSums::mean() const {
  LineSample m;
  if (!(rays > 0.0)) return m;
  for (size_t t = 0; t < coverage.size(); ++t) m.coverage[t] = float(coverage[t] / rays);
  m.weight = float(weight / rays);
  m.override_weight = float(override_weight / rays);
  m.override_color = Color(override_color / rays);
  m.rays = float(rays);
  m.hit_rays = float(hit_rays);
  return m;
}

Film::Film(int width, int height, AovSet aovs, bool lines) : width_(width), height_(height), aovs_(aovs) {
  const size_t n = size_t(width) * size_t(height);
  for (int h = 0; h < 2; ++h) {
    sum_[h].assign(n, glm::dvec3(0.0));
    count_[h].assign(n, 0);
  }
  // Pay only for what is asked for: a render keeps only the AOVs it was asked for.
  if (aovs.has(Aov::albedo)) albedo_sum_.assign(n, glm::dvec3(0.0));
  if (aovs.has(Aov::normal)) normal_sum_.assign(n, glm::dvec3(0.0));
  if (aovs.has(Aov::depth)) depth_sum_.assign(n, 0.0);
  if (aovs.has(Aov::toon_band)) band_sum_.assign(n, 0.0);
  if (aovs.averages_hits()) hit_count_.assign(n, 0);
  if (aovs.has(Aov::object_id)) object_id_.assign(n, -2);
  if (aovs.has(Aov::material_id)) material_id_.assign(n, -2);
  if (aovs.has(Aov::object_id) || aovs.has(Aov::material_id)) ids_mixed_.assign(n, 0);
  if (lines) {
    line_sum_.assign(n, LineSums{});
    line_count_.assign(n, 0);
  }
}

namespace {

// Fills a buffer in chunks across the caller's threads: a film of the full image is
// some hundred megabytes, which one thread takes tens of milliseconds to clear.
template <class T>
void fill_parallel(std::vector<T>& buffer, const T& value) {
  parallel_for_chunks(buffer.size(), size_t(1) << 16, [&](size_t begin, size_t end) {
    std::fill(buffer.begin() + std::ptrdiff_t(begin), buffer.begin() + std::ptrdiff_t(end), value);
  });
}

}  // namespace

void Film::clear() {
  // In place: a film cleared for a new accumulation keeps its memory (a new one of the
  // full image costs tens of milliseconds of page faults).
  for (auto& sums : sum_) fill_parallel(sums, glm::dvec3(0.0));
  for (auto& counts : count_) fill_parallel(counts, 0u);
  fill_parallel(albedo_sum_, glm::dvec3(0.0));
  fill_parallel(normal_sum_, glm::dvec3(0.0));
  fill_parallel(depth_sum_, 0.0);
  fill_parallel(band_sum_, 0.0);
  fill_parallel(hit_count_, 0u);
  fill_parallel(object_id_, -2);
  fill_parallel(material_id_, -2);
  fill_parallel(ids_mixed_, uint8_t(0));
  fill_parallel(line_sum_, LineSums{});
  fill_parallel(line_count_, 0u);
  nonfinite_ = 0;
}

void Film::clear_region(int x0, int y0, int x1, int y1) {
  for (int y = std::max(y0, 0); y < std::min(y1, height_); ++y) {
    for (int x = std::max(x0, 0); x < std::min(x1, width_); ++x) {
      const size_t i = index(x, y);
      for (int half = 0; half < 2; ++half) {
        sum_[size_t(half)][i] = glm::dvec3(0.0);
        count_[size_t(half)][i] = 0;
      }
      if (!albedo_sum_.empty()) albedo_sum_[i] = glm::dvec3(0.0);
      if (!normal_sum_.empty()) normal_sum_[i] = glm::dvec3(0.0);
      if (!depth_sum_.empty()) depth_sum_[i] = 0.0;
      if (!band_sum_.empty()) band_sum_[i] = 0.0;
      if (!hit_count_.empty()) hit_count_[i] = 0;
      if (!object_id_.empty()) object_id_[i] = -2;
      if (!material_id_.empty()) material_id_[i] = -2;
      if (!ids_mixed_.empty()) ids_mixed_[i] = 0;
      if (!line_sum_.empty()) {
        line_sum_[i] = LineSums{};
        line_count_[i] = 0;
      }
    }
  }
}

FilmPixel Film::pixel(int x, int y) const {
  const size_t i = index(x, y);
  FilmPixel p;
  for (size_t half = 0; half < 2; ++half) {
    p.sum[half] = sum_[half][i];
    p.count[half] = count_[half][i];
  }
  if (!albedo_sum_.empty()) p.albedo_sum = albedo_sum_[i];
  if (!normal_sum_.empty()) p.normal_sum = normal_sum_[i];
  if (!depth_sum_.empty()) p.depth_sum = depth_sum_[i];
  if (!band_sum_.empty()) p.band_sum = band_sum_[i];
  if (!hit_count_.empty()) p.hit_count = hit_count_[i];
  if (!object_id_.empty()) p.object_id = object_id_[i];
  if (!material_id_.empty()) p.material_id = material_id_[i];
  if (!ids_mixed_.empty()) p.ids_mixed = ids_mixed_[i];
  if (!line_sum_.empty()) {
    p.lines = line_sum_[i];
    p.line_count = line_count_[i];
  }
  return p;
}

void Film::add_pixel(int x, int y, const FilmPixel& p) {
  const size_t i = index(x, y);
  for (size_t half = 0; half < 2; ++half) {
    sum_[half][i] += p.sum[half];
    count_[half][i] += p.count[half];
  }
  if (!albedo_sum_.empty()) albedo_sum_[i] += p.albedo_sum;
  if (!normal_sum_.empty()) normal_sum_[i] += p.normal_sum;
  if (!depth_sum_.empty()) depth_sum_[i] += p.depth_sum;
  if (!band_sum_.empty()) band_sum_[i] += p.band_sum;
  if (!hit_count_.empty()) hit_count_[i] += p.hit_count;
  if (!ids_mixed_.empty()) {
    uint8_t mixed = uint8_t(ids_mixed_[i] | p.ids_mixed);
    if (!object_id_.empty() && object_id_[i] != -2 && p.object_id != -2 && p.object_id != object_id_[i])
      mixed |= 1u;
    if (!material_id_.empty() && material_id_[i] != -2 && p.material_id != -2 &&
        p.material_id != material_id_[i])
      mixed |= 2u;
    ids_mixed_[i] = mixed;
  }
  if (!object_id_.empty() && object_id_[i] == -2) object_id_[i] = p.object_id;
  if (!material_id_.empty() && material_id_[i] == -2) material_id_[i] = p.material_id;
  if (!line_sum_.empty()) {
    line_sum_[i].add(p.lines);
    line_count_[i] += p.line_count;
  }
}

void Film::add_sample(int x, int y, uint32_t pass, const Color& radiance) {
  const size_t i = index(x, y);
  if (!is_finite(radiance)) {
    nonfinite_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  const uint32_t half = half_of_pass(pass);
  ++count_[half][i];
  sum_[half][i] += glm::dvec3(radiance);
}

void Film::add_first_hit(int x, int y, const FirstHit& hit) {
  const size_t i = index(x, y);
  // Ids are not averaged: the first sample's id stands for the pixel.
  if (!object_id_.empty()) {
    if (object_id_[i] == -2)
      object_id_[i] = hit.object;
    else if (object_id_[i] != hit.object)
      ids_mixed_[i] |= 1u;
  }
  if (!material_id_.empty()) {
    if (material_id_[i] == -2)
      material_id_[i] = hit.material;
    else if (material_id_[i] != hit.material)
      ids_mixed_[i] |= 2u;
  }
  if (hit_count_.empty() || hit.object < 0) return;
  ++hit_count_[i];
  if (!albedo_sum_.empty()) albedo_sum_[i] += glm::dvec3(hit.albedo);
  if (!normal_sum_.empty()) normal_sum_[i] += glm::dvec3(hit.normal);
  if (!depth_sum_.empty()) depth_sum_[i] += double(hit.depth);
  if (!band_sum_.empty()) band_sum_[i] += double(hit.band);
}

void Film::add_lines(int x, int y, const LineSample& lines) {
  const size_t i = index(x, y);
  line_sum_[i].add(lines);
  ++line_count_[i];
}

LineSample Film::line_mean(int x, int y) const {
  if (line_sum_.empty()) return {};
  return line_sum_[index(x, y)].mean();
}

double Film::half_luminance(int x, int y, int half) const {
  const size_t i = index(x, y);
  const uint32_t n = count_[size_t(half)][i];
  return n ? dluminance(sum_[size_t(half)][i]) / double(n) : 0.0;
}

uint32_t Film::samples_at(int x, int y) const { return count_[0][index(x, y)] + count_[1][index(x, y)]; }

RgbImage Film::resolve() const {
  RgbImage img{width_, height_, std::vector<Color>(size_t(width_) * size_t(height_), Color(0.f))};
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const uint32_t n = count_[0][i] + count_[1][i];
    if (n) img.pixels[i] = Color((sum_[0][i] + sum_[1][i]) / double(n));
  }
  return img;
}

Color Film::mean_radiance(int x, int y) const {
  const size_t i = index(x, y);
  const uint32_t n = count_[0][i] + count_[1][i];
  return n ? Color((sum_[0][i] + sum_[1][i]) / double(n)) : Color(0.f);
}

Film::Surface Film::surface(int x, int y) const {
  const size_t i = index(x, y);
  Surface s;
  if (!depth_sum_.empty() && hit_count_[i]) s.depth = float(depth_sum_[i] / double(hit_count_[i]));
  if (!object_id_.empty()) s.object = std::max(object_id_[i], -1);
  if (!material_id_.empty()) s.material = std::max(material_id_[i], -1);
  return s;
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
    const double hits = hit_count_.empty() ? 0.0 : double(hit_count_[i]);
    switch (aov) {
      case Aov::albedo:
        img.pixels[i] = hits > 0.0 ? Color(albedo_sum_[i] / hits) : Color(0.f);
        break;
      case Aov::normal: {
        const glm::dvec3 n = normal_sum_[i];
        img.pixels[i] = glm::length(n) > 0.0 ? Vec3(glm::normalize(n)) : Vec3(0.f);
        break;
      }
      case Aov::depth:
        img.pixels[i] = Color(hits > 0.0 ? float(depth_sum_[i] / hits) : 0.f);
        break;
      case Aov::object_id:
        img.pixels[i] = Color(float(object_id_[i] < -1 ? -1 : object_id_[i]));
        break;
      case Aov::material_id:
        img.pixels[i] = Color(float(material_id_[i] < -1 ? -1 : material_id_[i]));
        break;
      case Aov::toon_band:
        img.pixels[i] = Color(hits > 0.0 ? float(band_sum_[i] / hits) : -1.f);
        break;
      default:
        break;  // outline AOVs are handled above
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
    const double a = dluminance(sum_[0][i]) / na, b = dluminance(sum_[1][i]) / nb;
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
    const double a = dluminance(sum_[0][i]) / na, b = dluminance(sum_[1][i]) / nb;
    const double mean = 0.5 * (a + b);
    if (mean <= 0.0) continue;
    img.pixels[i] = Color(float(std::abs(a - b) * 0.5 / mean));
  }
  return img;
}

}  // namespace inkray
