// inkray-bench-meshes: what mesh preparation costs on a million triangles (a
// noisy torus, as a scanned mesh): feature edges (once per mesh), smooth
// patches at a crease threshold (on every threshold edit) and auto-smooth
// normals (at load and on every smooth_angle edit). Median of --runs N.
#include "core/geometry/mesh_features.h"
#include "core/geometry/mesh_normals.h"
#include "core/geometry/obj_loader.h"
#include "core/geometry/triangle_mesh.h"
#include "bench/bench_stats.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

namespace inkray {
namespace {

// A noisy closed torus of about a million triangles, as a scanned mesh.
TriangleMeshData million_triangles() {
  const int nu = 1000, nv = 500;
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.f, 0.0005f);
  std::vector<Point3> p;
  std::vector<uint32_t> idx;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const float u = 2.f * kPi * float(i) / float(nu), v = 2.f * kPi * float(j) / float(nv);
      const float r = 0.4f + noise(rng);
      p.emplace_back((1.f + r * std::cos(v)) * std::cos(u), r * std::sin(v),
                     (1.f + r * std::cos(v)) * std::sin(u));
    }
  }
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const uint32_t a = uint32_t(i * nv + j), b = uint32_t(((i + 1) % nu) * nv + j),
                     c = uint32_t(((i + 1) % nu) * nv + (j + 1) % nv), d = uint32_t(i * nv + (j + 1) % nv);
      idx.insert(idx.end(), {a, b, c, a, c, d});
    }
  }
  return TriangleMeshData{std::move(p), {}, {}, std::move(idx)};
}

}  // namespace
}  // namespace inkray

int main(int argc, char** argv) {
  using namespace inkray;
  int runs = 3;
  for (int i = 1; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], "--runs")) runs = std::max(std::atoi(argv[i + 1]), 1);
  const TriangleMeshData mesh = million_triangles();
  std::printf("noisy torus, %zu triangles, median of %d runs (one thread)\n", mesh.indices.size() / 3, runs);
  MeshFeatures features;
  std::printf("feature edges            %8.1f ms\n",
              bench::median_ms(runs, [&] { features = find_feature_edges(mesh.positions, mesh.indices); }));
  for (const float threshold : {30.f, 60.f}) {
    size_t patches = 0;
    const double ms = bench::median_ms(runs, [&] {
      const std::vector<uint32_t> ids = smooth_patches(features, threshold);
      patches = ids.empty() ? 0 : size_t(*std::max_element(ids.begin(), ids.end())) + 1;
    });
    std::printf("patches at %3.0f degrees    %8.1f ms (%zu patches)\n", double(threshold), ms, patches);
  }
  size_t vertices = 0;
  std::printf("auto smooth at 30 degrees %7.1f ms",
              bench::median_ms(runs, [&] { vertices = auto_smooth(mesh, 30.f).positions.size(); }));
  std::printf(" (%zu vertices)\n", vertices);
  return 0;
}
