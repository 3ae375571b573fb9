// Fuzz harness for the partial reader (film_partial.h): files encoded in-process from
// small films, damaged as the input says (file_edits_fuzz.h); the oracle is
// partial_oracle_fuzz.h's.
#include "tests/fuzz/partial_oracle_fuzz.h"
#include "tests/support/odd_film.h"

namespace inkray {
namespace {

PartialInfo info_of(int w, int h, PixelWindow window) {
  return {
      .width = w,
      .height = h,
      .window = window,
      .first_pass = 3,
      .end_pass = 6,
      .frame = 2.5f,
      .seed = 7,
      .scene =
          R"({"format": "inkray-scene", "render": {"spp": 4, "max_depth": 8}, "objects": [{"name": "a"}]})",
      .assets = {{"meshes/bunny.obj", "0123456789abcdef"}, {"textures/wood.png", "missing"}}};
}

std::vector<partial_oracle::Seed> seeds() {
  AovSet every;
  for (const Aov a : {Aov::albedo, Aov::normal, Aov::depth, Aov::toon_band, Aov::object_id, Aov::material_id})
    every.add(a);
  AovSet depth;
  depth.add(Aov::depth);
  std::vector<partial_oracle::Seed> v;
  v.push_back(partial_oracle::make_seed(*testing::odd_film(6, 5, every, true), info_of(6, 5, {1, 1, 6, 4})));
  // 256 pixels or more are RLE compressed.
  v.push_back(
      partial_oracle::make_seed(*testing::odd_film(18, 16, {}, false), info_of(18, 16, {2, 0, 18, 16})));
  v.push_back(partial_oracle::make_seed(*testing::odd_film(4, 3, depth, true), info_of(4, 3, {0, 0, 4, 3})));
  return v;
}

}  // namespace

int fuzz_partial_reader(const std::uint8_t* data, std::size_t size) {
  return partial_oracle::run<seeds>(data, size);
}

}  // namespace inkray
