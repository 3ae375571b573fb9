#include "core/render/render_session.h"

#include "core/integrator/path_tracer.h"
#include "core/npr/outlines/line_sampling.h"

#include <cmath>

namespace inkray {
namespace {

// Offset of a sample from the pixel centre, importance-sampled from the pixel
// filter so every sample has weight 1 and stays in its own pixel's sums.
Vec2 filter_offset(const RenderSettings& settings, Vec2 u) {
  const float r = settings.filter_radius;
  if (settings.filter == PixelFilter::box) return (2.f * u - Vec2(1.f)) * r;
  // Gaussian with sigma = r / 3 (Box-Muller); the rare tail beyond r is clamped.
  const float sigma = r / 3.f;
  const float radius = sigma * std::sqrt(-2.f * std::log(std::max(1.f - u.x, 1e-12f)));
  const float phi = 2.f * kPi * u.y;
  return glm::clamp(Vec2(radius * std::cos(phi), radius * std::sin(phi)), Vec2(-r), Vec2(r));
}

}  // namespace

RenderSession::RenderSession(int threads) : pool_(threads), worker_rays_(size_t(pool_.size()), 0) {}

void RenderSession::set_scene(std::shared_ptr<const RenderScene> scene, AovSet aovs, int divisor) {
  scene_ = std::move(scene);
  divisor_ = std::max(divisor, 1);
  const int width = std::max((scene_->settings.width + divisor_ - 1) / divisor_, 1);
  const int height = std::max((scene_->settings.height + divisor_ - 1) / divisor_, 1);
  lines_ = make_line_setup(*scene_, divisor_);
  film_ = std::make_unique<Film>(width, height, aovs, lines_.active);
  stats_ = {};
  tiles_done_.clear();
  near_line_.clear();
}

bool RenderSession::render_pass() {
  cancelled_.store(false, std::memory_order_relaxed);
  const auto start = std::chrono::steady_clock::now();
  const int tiles_x = (film_->width() + kTileSize - 1) / kTileSize;
  const int tiles_y = (film_->height() + kTileSize - 1) / kTileSize;
  const uint32_t pass = stats_.passes;
  // A pass cancelled before resumes where it stopped: its finished tiles already
  // hold this pass's sample, and a second would repeat it.
  if (tiles_done_.size() != size_t(tiles_x * tiles_y)) tiles_done_.assign(size_t(tiles_x * tiles_y), 0);
  std::fill(worker_rays_.begin(), worker_rays_.end(), 0);
  pool_.parallel_for(tiles_x * tiles_y, [&](int tile, int worker) {
    if (tiles_done_[size_t(tile)] || cancelled_.load(std::memory_order_relaxed)) return;
    render_tile(tile, worker, pass);
    tiles_done_[size_t(tile)] = 1;
  });
  stats_.elapsed_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (cancelled_.load(std::memory_order_relaxed)) return false;
  std::fill(tiles_done_.begin(), tiles_done_.end(), 0);
  if (lines_.active && lines_.adaptive && stats_.passes + 1 >= kLineProbeSamples)
    mark_line_neighbourhoods(*film_, lines_, near_line_);
  ++stats_.passes;
  ++stats_.spp;
  for (uint64_t r : worker_rays_) stats_.rays += r;
  stats_.paths += uint64_t(film_->width()) * uint64_t(film_->height());
  stats_.nonfinite_samples = film_->nonfinite_samples();
  stats_.relative_error = stats_.passes >= 2 ? film_->estimated_relative_error() : 0.0;
  return true;
}

void RenderSession::render_tile(int tile, int worker, uint32_t pass) {
  const RenderScene& scene = *scene_;
  const int tiles_x = (film_->width() + kTileSize - 1) / kTileSize;
  const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
  int x1 = std::min(x0 + kTileSize, film_->width()), y1 = std::min(y0 + kTileSize, film_->height());
  const auto [rx0, ry0, rx1, ry1] = region_;
  const bool has_region = rx1 > rx0 && ry1 > ry0;
  const int sx0 = has_region ? std::max(x0, rx0) : x0, sy0 = has_region ? std::max(y0, ry0) : y0;
  if (has_region) x1 = std::min(x1, rx1), y1 = std::min(y1, ry1);
  const float scale = float(divisor_);
  const Camera& camera = scene.camera;
  const bool want_first_hit = film_->aovs().any_first_hit();
  const float clamp = scene.settings.clamp;
  const uint32_t seed = uint32_t(scene.settings.seed);
  uint64_t rays = 0;
  for (int y = sy0; y < y1; ++y) {
    for (int x = sx0; x < x1; ++x) {
      const Sampler sampler(uint32_t(x), uint32_t(y), pass, seed);
      const Vec2 film_pos =
          (Vec2(float(x) + 0.5f, float(y) + 0.5f) + filter_offset(scene.settings, sampler.get_pair(0))) * scale;
      const Vec2 lens = sampler.get_pair(1);
      const Ray ray = camera.generate_ray(film_pos, lens);
      FirstHit first_hit;
      PrimaryHit primary;
      // Adaptive line sampling decides before the path is traced, so a sample
      // that needs no lines does not keep the camera hit for them.
      StencilDraw draw;
      if (lines_.active) {
        const LineSample& so_far = film_->line_sum(x, y);
        draw = {uint32_t(x), uint32_t(y), uint32_t(so_far.rays), seed,
                stencil_rays(lines_, so_far, film_->line_samples(x, y), near_line(x, y), uint32_t(x), uint32_t(y), pass, seed)};
      }
      const bool lines = lines_.active && draw.count > 0;
      PathResult r =
          trace_path(scene, camera, ray, sampler, want_first_hit ? &first_hit : nullptr, lines ? &primary : nullptr);
      if (lines) {
        const float u_mix = sampler.get_pair(kFirstHitMixPair).x;
        film_->add_lines(x, y, detect_lines(scene, lines_, camera, film_pos, lens, ray, primary, u_mix, draw, &r.rays));
      }
      rays += r.rays;
      if (clamp > 0.f) {
        const float lum = luminance(r.radiance);
        if (lum > clamp) r.radiance *= clamp / lum;
      }
      film_->add_sample(x, y, pass, r.radiance);
      if (want_first_hit) film_->add_first_hit(x, y, first_hit);
    }
  }
  worker_rays_[size_t(worker)] += rays;
}

}  // namespace inkray
