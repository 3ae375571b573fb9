// Fuzz harness for checkpoints as inkray-render --resume reads them: partials cut in
// the middle of a pass, whose inkray.passInProgress lists the tiles of that pass already
// in the sums. Damaged as the input says (file_edits_fuzz.h); partial_oracle_fuzz.h's
// oracle, whose checks include what --resume relies on: one flag per 16x16 tile.
#include "tests/fuzz/partial_oracle_fuzz.h"

namespace inkray {
namespace {

std::unique_ptr<Film> checkpoint_film(int w, int h, const std::vector<uint8_t>& tiles, bool aovs_and_lines) {
  AovSet aovs;
  if (aovs_and_lines)
    for (const Aov a : {Aov::albedo, Aov::depth, Aov::object_id}) aovs.add(a);
  auto film = std::make_unique<Film>(w, h, aovs, aovs_and_lines);
  const int tiles_x = (w + 15) / 16;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Passes 0-3 everywhere, pass 4 on the tiles done.
      const bool done = tiles[size_t((y / 16) * tiles_x + x / 16)] != 0;
      for (uint32_t pass = 0; pass < (done ? 5u : 4u); ++pass) {
        film->add_sample(x, y, pass, Color(float(x) / 7.f, float(y) / 3.f, float(pass)));
        film->add_first_hit(
            x, y, {.albedo = Color(0.25f * float(pass)), .depth = float(x) + 0.5f, .object = (x + y) % 4});
        if (!aovs_and_lines) continue;
        film->add_lines(x, y, {.coverage = {float(y) / 11.f}, .weight = 1.f, .rays = 4.f});
      }
    }
  return film;
}

partial_oracle::Seed seed(int w, int h, std::vector<uint8_t> tiles, bool aovs_and_lines = true) {
  const PartialInfo info{.width = w,
                         .height = h,
                         .window = {0, 0, w, h},
                         .first_pass = 0,
                         .end_pass = 4,
                         .tiles_done = tiles,
                         .frame = 4.f,
                         .seed = 11,
                         .scene = R"({"format": "inkray-scene", "render": {"spp": 64}})",
                         .assets = {{"meshes/knot.obj", "fedcba9876543210"}}};
  return partial_oracle::make_seed(*checkpoint_film(w, h, tiles, aovs_and_lines), info);
}

std::vector<partial_oracle::Seed> seeds() {
  std::vector<partial_oracle::Seed> v;
  // Small: the harness's time goes with the file's size.
  v.push_back(seed(33, 1, {1, 0, 1}));       // 3x1 tiles
  v.push_back(seed(5, 3, {1}));              // one tile
  v.push_back(seed(17, 16, {0, 1}, false));  // RLE (256 pixels or more), no AOVs or lines
  return v;
}

}  // namespace

int fuzz_checkpoint_reader(const std::uint8_t* data, std::size_t size) {
  return partial_oracle::run<seeds>(data, size);
}

}  // namespace inkray
