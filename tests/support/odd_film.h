// A small film whose every channel holds values no float round trip would keep
// (thirds, a tiny and a huge sum), with ids, AOVs and line sums: what the tests and
// the fuzz harnesses of the partial files encode, damage and read back.
#pragma once

#include "core/film/film.h"

#include <memory>

namespace inkray::testing {

inline AovSet every_first_hit_aov() {
  AovSet a;
  for (const Aov aov : {Aov::albedo, Aov::normal, Aov::depth, Aov::object_id, Aov::material_id}) a.add(aov);
  return a;
}

inline std::unique_ptr<Film> odd_film(int w, int h, AovSet aovs = every_first_hit_aov(), bool lines = true) {
  auto film = std::make_unique<Film>(w, h, aovs, lines);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (uint32_t pass = 0; pass < 3; ++pass) {
        const float v = float(x + 1) / 3.f + float(y) * 1e-7f + float(pass);
        film->add_sample(x, y, pass, Color(v, v * 1e-30f, v * 1e30f));
        FirstHit hit;
        hit.object = x == 0 ? -1 : x + int(pass);
        hit.material = y;
        hit.albedo = Color(v);
        hit.normal = Vec3(0.f, 1.f, v);
        hit.depth = v * 7.f;
        hit.band = v / 5.f;
        film->add_first_hit(x, y, hit);
        if (!lines) continue;
        LineSample s;
        s.coverage[2] = v / 7.f;
        s.weight = v;
        s.override_color = Color(0.1f, v, 0.3f);
        s.rays = 3.f;
        s.hit_rays = 1.f;
        film->add_lines(x, y, s);
      }
  return film;
}

}  // namespace inkray::testing
