#include "core/render/render_session.h"

#include "core/film/film_chains.h"

#include "core/integrator/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace inkray {
namespace {

// Offset of a sample from the pixel centre, importance-sampled from the pixel
// filter so every sample has weight 1 and stays in its own pixel's sums.
Vec2 filter_offset(const SampleSettings& settings, Vec2 u) {
  const float r = settings.filter_radius;
  if (settings.filter == PixelFilter::box) return (2.f * u - Vec2(1.f)) * r;
  // Gaussian with sigma = r / 3 (Box-Muller); the rare tail beyond r is clamped.
  const float sigma = r / 3.f;
  const float radius = sigma * std::sqrt(-2.f * std::log(std::max(1.f - u.x, 1e-12f)));
  const float phi = 2.f * kPi * u.y;
  return glm::clamp(Vec2(radius * std::cos(phi), radius * std::sin(phi)), Vec2(-r), Vec2(r));
}

// The camera sample of pixel (x, y): where on the film and the lens its ray starts.
struct CameraSample {
  Vec2 film_pos, lens;
  Ray ray;
};

CameraSample camera_sample(const RenderScene& scene, const Sampler& sampler, int x, int y, float scale) {
  CameraSample s;
  s.film_pos =
      (Vec2(float(x) + 0.5f, float(y) + 0.5f) + filter_offset(scene.sampling, sampler.get_pair(0))) * scale;
  s.lens = sampler.get_pair(1);
  // The sample's instant of the shutter, drawn only while it is open for a time:
  // without motion blur every sample stream is as it was.
  const float time = scene.sampling.motion_blur ? sampler.get_time() : 0.f;
  s.ray = scene.camera.generate_ray(s.film_pos, s.lens, time);
  return s;
}

// What trace_path's first intersection reports as PrimaryHit, without the path.
PrimaryHit camera_hit(const RenderScene& scene, const Ray& ray) {
  PrimaryHit primary;
  Hit hit;
  if (!scene.world->geometry.intersect(ray, kInfinity, &hit, RayKind::camera)) return primary;
  primary.hit = true;
  primary.si = scene.world->geometry.interaction(ray, hit);
  primary.distance = 0.f + hit.t * glm::length(ray.d);
  return primary;
}

}  // namespace

RenderSession::RenderSession(int threads) : pool_(threads), worker_rays_(size_t(pool_.size()), 0) {}

void RenderSession::set_scene(std::shared_ptr<const RenderScene> scene, AovSet aovs, int divisor) {
  scene_ = std::move(scene);
  divisor_ = std::max(divisor, 1);
  const int width = std::max((scene_->sampling.width + divisor_ - 1) / divisor_, 1);
  const int height = std::max((scene_->sampling.height + divisor_ - 1) / divisor_, 1);
  lines_ = line_setup_for_film(scene_->lines, divisor_);
  // Line sets draw chains labelled with the surfaces under them (film_chains.h).
  if (lines_.active && !scene_->resolve.sets.empty()) aovs.bits |= chain_aovs().bits;
  film_ = film_for(width, height, aovs, lines_.active);
  stats_ = {};
  first_pass_ = 0;
  tiles_done_.clear();
  line_pixels_.clear();
  if (lines_.active) line_pixels_.assign(size_t(width) * size_t(height), LinePixel{});
  reset_adaptive();
}

std::unique_ptr<Film> RenderSession::film_for(int width, int height, AovSet aovs, bool lines) {
  if (film_) spare_films_.push_back(std::move(film_));
  const auto fits = [&](const std::unique_ptr<Film>& f) {
    return f->width() == width && f->height() == height && f->aovs().bits == aovs.bits &&
           f->has_lines() == lines;
  };
  if (const auto spare = std::find_if(spare_films_.begin(), spare_films_.end(), fits);
      spare != spare_films_.end()) {
    std::unique_ptr<Film> film = std::move(*spare);
    spare_films_.erase(spare);
    // Within the session's threads, as everything it runs (core/base/parallel.h).
    pool_.run([&] { film->clear(); });
    return film;
  }
  if (spare_films_.size() > kSpareFilms) spare_films_.erase(spare_films_.begin());
  return std::make_unique<Film>(width, height, aovs, lines);
}

void RenderSession::set_adaptive(const AdaptiveSampling& adaptive) {
  // Stopped tiles stay stopped under the same or a looser threshold; a tighter one, or
  // none, sets every tile sampling again.
  const bool keep = adaptive.on() && adaptive_.on() && adaptive.threshold >= adaptive_.threshold;
  adaptive_ = adaptive;
  if (!keep) reset_adaptive();
}

void RenderSession::reset_adaptive() {
  if (!film_) return;
  tile_active_.assign(size_t(tile_count()), 1);
  const TileGrid grid = tile_grid();
  const PixelWindow w = active_window();
  uint32_t n = 0;
  for (int t = 0; t < grid.count(); ++t) {
    const PixelWindow tw = grid.window(t);
    n += tw.x1 > w.x0 && tw.x0 < w.x1 && tw.y1 > w.y0 && tw.y0 < w.y1;
  }
  stats_.active_tiles = stats_.tiles = n;
}

void RenderSession::update_adaptive() {
  // Decided with both halves holding the same passes, once every tile has the minimum.
  if (!adaptive_.on() || stats_.passes % 2 != 0 || stats_.spp < std::max(adaptive_.min_spp, 2u)) return;
  stats_.active_tiles = uint32_t(
      stop_converged_tiles(*film_, tile_grid(), active_window(), adaptive_, line_pixels_, tile_active_));
}

void RenderSession::restart_region(int x0, int y0, int x1, int y1) {
  film_->clear_region(x0, y0, x1, y1);
  stats_ = {};
  first_pass_ = 0;
  tiles_done_.clear();
  set_region(x0, y0, x1, y1);  // every tile of the region samples again
  // The region's pixels probe again; those around it keep what they know, which
  // the region's line map reads.
  if (line_pixels_.empty()) return;
  const PixelWindow w = active_window();
  for (int y = w.y0; y < w.y1; ++y)
    for (int x = w.x0; x < w.x1; ++x)
      line_pixels_[size_t(y) * size_t(film_->width()) + size_t(x)] = LinePixel{};
}

PixelWindow RenderSession::active_window() const {
  const PixelWindow whole{0, 0, film_->width(), film_->height()};
  if (region_.empty()) return whole;
  return {std::max(region_.x0, 0), std::max(region_.y0, 0), std::min(region_.x1, whole.x1),
          std::min(region_.y1, whole.y1)};
}

PixelWindow RenderSession::tile_window(int tile) const { return tile_grid().window(tile); }

template <class F>
void RenderSession::for_margin_pixels(int tile, uint32_t pass, F&& f) const {
  if (!lines_.active || !lines_.adaptive || pass >= kLineProbeSamples || region_.empty()) return;
  const PixelWindow r = active_window(), t = tile_window(tile);
  const int reach = line_reach(lines_);
  const int y0 = std::max(t.y0, r.y0 - reach), y1 = std::min(t.y1, r.y1 + reach);
  const int x0 = std::max(t.x0, r.x0 - reach), x1 = std::min(t.x1, r.x1 + reach);
  const uint32_t probed = pass * uint32_t(lines_.quality);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      if (r.contains(x, y)) continue;
      // Only pixels that have probed exactly the passes before: a pixel rendered
      // before (the editor's region inside a finished film) keeps what it knows.
      const LinePixel& p = line_pixels_[size_t(y) * size_t(film_->width()) + size_t(x)];
      if (p.kind == LineKind::probing && p.rays == probed) f(x, y);
    }
}

void RenderSession::finish_probes(uint32_t pass) {
  if (lines_.active && lines_.adaptive && pass + 1 == kLineProbeSamples)
    mark_line_neighbourhoods(line_pixels_, film_->width(), film_->height(), lines_, active_window());
}

int RenderSession::tile_count() const { return tile_grid().count(); }

bool RenderSession::render_pass() {
  const auto start = std::chrono::steady_clock::now();
  const int tiles = tile_count();
  const uint32_t pass = stats_.passes;
  // A pass cancelled before resumes where it stopped: its finished tiles already
  // hold this pass's sample, and a second would repeat it.
  if (tiles_done_.size() != size_t(tiles)) tiles_done_.assign(size_t(tiles), 0);
  if (tile_active_.size() != size_t(tiles)) reset_adaptive();
  std::fill(worker_rays_.begin(), worker_rays_.end(), 0);
  pool_.parallel_for(tiles, [&](int tile, int worker) {
    if (tiles_done_[size_t(tile)] || !tile_active_[size_t(tile)] ||
        cancelled_.load(std::memory_order_relaxed))
      return;
    render_tile(tile, worker, pass);
    tiles_done_[size_t(tile)] = 1;
  });
  stats_.elapsed_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The cancel is spent on this pass. One that came before the pass began stopped it
  // too: it was meant for work not yet done (a time limit reached between passes, a
  // viewport request the worker has not taken yet).
  if (cancelled_.exchange(false, std::memory_order_relaxed)) return false;
  std::fill(tiles_done_.begin(), tiles_done_.end(), 0);
  finish_probes(pass);
  ++stats_.passes;
  ++stats_.spp;
  for (uint64_t r : worker_rays_) stats_.rays += r;
  uint64_t paths = 0;
  const PixelWindow r = active_window();
  for (int t = 0; t < tiles; ++t) {
    if (!tile_active_[size_t(t)]) continue;
    const PixelWindow w = tile_window(t);
    paths += uint64_t(std::max(0, std::min(w.x1, r.x1) - std::max(w.x0, r.x0))) *
             uint64_t(std::max(0, std::min(w.y1, r.y1) - std::max(w.y0, r.y0)));
  }
  stats_.paths += paths;
  stats_.nonfinite_samples = film_->nonfinite_samples();
  stats_.relative_error = stats_.spp >= 2 ? film_->estimated_relative_error() : 0.0;
  update_adaptive();
  return true;
}

LineSample RenderSession::trace_lines_only(int x, int y, uint32_t pass, int count, uint64_t* rays) const {
  const RenderScene& scene = *scene_;
  const uint32_t seed = scene.sampling.seed;
  const Sampler sampler(uint32_t(x), uint32_t(y), pass, seed);
  const CameraSample cs = camera_sample(scene, sampler, x, y, float(divisor_));
  const PrimaryHit primary = camera_hit(scene, cs.ray);
  const LinePixel& p = line_pixels_[size_t(y) * size_t(film_->width()) + size_t(x)];
  const StencilDraw draw{uint32_t(x), uint32_t(y), p.rays, seed, count};
  uint32_t traced = 1;
  const LineSample s = detect_lines(scene, lines_, scene.camera, cs.film_pos, cs.lens, cs.ray, primary,
                                    sampler.get_pair(kFirstHitMixPair).x, draw, &traced);
  *rays += traced;
  return s;
}

void RenderSession::render_tile(int tile, int worker, uint32_t pass) {
  const RenderScene& scene = *scene_;
  const PixelWindow t = tile_window(tile), r = active_window();
  const int x0 = std::max(t.x0, r.x0), x1 = std::min(t.x1, r.x1);
  const int y0 = std::max(t.y0, r.y0), y1 = std::min(t.y1, r.y1);
  const float scale = float(divisor_);
  const Camera& camera = scene.camera;
  const bool want_first_hit = film_->aovs().any_first_hit();
  const float clamp = scene.sampling.clamp;
  const uint32_t seed = scene.sampling.seed;
  const size_t width = size_t(film_->width());
  uint64_t rays = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const Sampler sampler(uint32_t(x), uint32_t(y), pass, seed);
      const CameraSample cs = camera_sample(scene, sampler, x, y, scale);
      FirstHit first_hit;
      PrimaryHit primary;
      // Adaptive line sampling decides before the path is traced, so a sample
      // that needs no lines does not keep the camera hit for them.
      StencilDraw draw;
      LinePixel* line_pixel = nullptr;
      if (lines_.active) {
        line_pixel = &line_pixels_[size_t(y) * width + size_t(x)];
        draw = {uint32_t(x), uint32_t(y), line_pixel->rays, seed,
                stencil_rays(lines_, *line_pixel, uint32_t(x), uint32_t(y), pass, seed)};
      }
      const bool lines = lines_.active && draw.count > 0;
      PathResult res = trace_path(scene, camera, cs.ray, sampler, want_first_hit ? &first_hit : nullptr,
                                  lines ? &primary : nullptr);
      if (lines) {
        const float u_mix = sampler.get_pair(kFirstHitMixPair).x;
        const LineSample found = detect_lines(scene, lines_, camera, cs.film_pos, cs.lens, cs.ray, primary,
                                              u_mix, draw, &res.rays);
        film_->add_lines(x, y, found);
        record_line_sample(lines_, *line_pixel, found);
      }
      rays += res.rays;
      if (clamp > 0.f) {
        const float lum = luminance(res.radiance);
        if (lum > clamp) res.radiance *= clamp / lum;
      }
      film_->add_sample(x, y, pass, res.radiance);
      if (want_first_hit) film_->add_first_hit(x, y, first_hit);
    }
  }
  for_margin_pixels(tile, pass, [&](int x, int y) {
    LinePixel& p = line_pixels_[size_t(y) * width + size_t(x)];
    const int count = stencil_rays(lines_, p, uint32_t(x), uint32_t(y), pass, seed);
    record_line_sample(lines_, p, trace_lines_only(x, y, pass, count, &rays));
  });
  worker_rays_[size_t(worker)] += rays;
}

void RenderSession::replay_tile(int tile, uint32_t pass) {
  const PixelWindow t = tile_window(tile), r = active_window();
  const uint32_t seed = scene_->sampling.seed;
  const size_t width = size_t(film_->width());
  uint64_t rays = 0;  // not counted: the session's statistics are of its own passes
  const auto replay = [&](int x, int y) {
    LinePixel& p = line_pixels_[size_t(y) * width + size_t(x)];
    const int count = stencil_rays(lines_, p, uint32_t(x), uint32_t(y), pass, seed);
    if (count <= 0) return;
    if (line_decision_pending(lines_, p)) {
      record_line_sample(lines_, p, trace_lines_only(x, y, pass, count, &rays));
    } else {
      p.rays += uint32_t(count);  // no decision reads these rays: their count is all that follows
    }
  };
  for (int y = std::max(t.y0, r.y0); y < std::min(t.y1, r.y1); ++y)
    for (int x = std::max(t.x0, r.x0); x < std::min(t.x1, r.x1); ++x) replay(x, y);
  for_margin_pixels(tile, pass, replay);
}

uint32_t RenderSession::replay_decisions(uint32_t next) {
  const PixelWindow r = active_window();
  const size_t width = size_t(film_->width());
  const int tiles = tile_count();
  uint32_t pass = 0;
  for (; pass < next; ++pass) {
    if (pass >= kLineProbeSamples || !lines_.adaptive) {
      bool pending = false;
      for (int y = r.y0; y < r.y1 && !pending; ++y)
        for (int x = r.x0; x < r.x1 && !pending; ++x)
          pending = line_decision_pending(lines_, line_pixels_[size_t(y) * width + size_t(x)]);
      if (!pending) break;
    }
    pool_.parallel_for(tiles, [&](int tile, int) { replay_tile(tile, pass); });
    finish_probes(pass);
  }
  return pass;
}

LineDecisions RenderSession::decide_lines() {
  LineDecisions d;
  d.width = film_->width();
  d.height = film_->height();
  if (!lines_.active) return d;
  const PixelWindow kept = region_;
  region_ = {};
  // Pending pixels decide within a few passes of the probes (each traces at least one
  // ray a pass until kMinSolidRays), so the bound is never reached.
  d.decided_at = replay_decisions(std::numeric_limits<uint32_t>::max());
  region_ = kept;
  d.rays.resize(line_pixels_.size());
  d.kinds.resize(line_pixels_.size());
  for (size_t i = 0; i < line_pixels_.size(); ++i) {
    d.rays[i] = line_pixels_[i].rays;
    d.kinds[i] = line_pixels_[i].kind;
    line_pixels_[i] = LinePixel{};
  }
  return d;
}

void RenderSession::continue_from(uint32_t first, uint32_t next, const std::vector<uint8_t>& tiles_done,
                                  const LineDecisions* decided) {
  const size_t tiles = size_t(tile_count());
  const bool in_progress = tiles_done.size() == tiles;
  if (lines_.active) {
    const PixelWindow r = active_window();
    const size_t width = size_t(film_->width());
    // Pass by pass while decisions are pending (or read where they were kept); then
    // each pixel's count at once.
    uint32_t pass = 0;
    if (decided && decided->decided_at <= next && decided->width == film_->width() &&
        decided->height == film_->height() && decided->rays.size() == line_pixels_.size() &&
        decided->kinds.size() == line_pixels_.size()) {
      for (size_t i = 0; i < line_pixels_.size(); ++i) {
        line_pixels_[i] = LinePixel{};
        line_pixels_[i].rays = decided->rays[i];
        line_pixels_[i].kind = decided->kinds[i];
      }
      pass = decided->decided_at;
    } else {
      pass = replay_decisions(next);
    }
    const uint32_t seed = scene_->sampling.seed;
    if (pass < next)
      pool_.parallel_for(r.height(), [&](int row, int) {
        const int y = r.y0 + row;
        for (int x = r.x0; x < r.x1; ++x) {
          LinePixel& p = line_pixels_[size_t(y) * width + size_t(x)];
          p.rays += stencil_rays_between(lines_, p, uint32_t(x), uint32_t(y), pass, next, seed);
        }
      });
    if (in_progress)
      pool_.parallel_for(int(tiles), [&](int tile, int) {
        if (tiles_done[size_t(tile)]) replay_tile(tile, next);
      });
  }
  first_pass_ = first;
  stats_ = {};
  stats_.passes = next;
  stats_.spp = next - first;
  stats_.nonfinite_samples = film_->nonfinite_samples();
  if (in_progress)
    tiles_done_ = tiles_done;
  else
    tiles_done_.clear();
  reset_adaptive();
}

void RenderSession::load_film(const Film& window_film) {
  const PixelWindow w = active_window();
  for (int y = 0; y < std::min(window_film.height(), w.height()); ++y)
    for (int x = 0; x < std::min(window_film.width(), w.width()); ++x)
      film_->add_pixel(w.x0 + x, w.y0 + y, window_film.pixel(x, y));
  film_->add_nonfinite(window_film.nonfinite_samples());
}

}  // namespace inkray
