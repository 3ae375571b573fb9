// Chains of a film's lines (film_chains.h).
#include "core/film/film_chains.h"

#include "core/npr/lines/chain_builder.h"

#include <algorithm>

namespace inkray {

AovSet chain_aovs() {
  AovSet a;
  for (Aov kept : {Aov::depth, Aov::object_id, Aov::material_id}) a.add(kept);
  return a;
}

std::vector<Chain> film_chains(const Film& film, const std::vector<uint8_t>& material_paths) {
  ChainSource s;
  s.width = film.width(), s.height = film.height();
  if (!film.has_lines() || s.width <= 0 || s.height <= 0) return {};
  const size_t n = size_t(s.width) * size_t(s.height);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const LineSample m = film.line_mean(x, y);
      if (!(m.weight > 0.f)) continue;
      std::array<float, kLineTypeCount> opacity{};
      for (int t = 0; t < kLineTypeCount; ++t) opacity[size_t(t)] = line_opacity(m.coverage[size_t(t)]);
      s.pixels.push_back(uint32_t(y) * uint32_t(s.width) + uint32_t(x));
      s.opacity.push_back(opacity);
    }
  // The layers are read within two pixels of a line (chain_builder.cpp's windows):
  // only there are they filled.
  s.depth.assign(n, 0.f);
  s.object.assign(n, -1);
  s.material.assign(n, -1);
  s.path.assign(n, uint8_t(LinePath::direct));
  s.light.assign(n, 0.f);
  std::vector<uint8_t> filled(n, 0);
  for (uint32_t p : s.pixels) {
    const int px = int(p % uint32_t(s.width)), py = int(p / uint32_t(s.width));
    for (int y = std::max(py - 2, 0); y <= std::min(py + 2, s.height - 1); ++y)
      for (int x = std::max(px - 2, 0); x <= std::min(px + 2, s.width - 1); ++x) {
        const size_t i = size_t(y) * size_t(s.width) + size_t(x);
        if (filled[i]) continue;
        filled[i] = 1;
        const Film::Surface surface = film.surface(x, y);
        s.depth[i] = surface.depth;
        s.object[i] = surface.object;
        s.material[i] = surface.material;
        if (surface.material >= 0 && size_t(surface.material) < material_paths.size())
          s.path[i] = material_paths[size_t(surface.material)];
        s.light[i] = std::min(luminance(film.mean_radiance(x, y)), 1.f);
      }
  }
  return build_chains(s);
}

}  // namespace inkray
