// Feature edges and smooth patches (core/geometry/mesh_features.h): edges found by
// position across split vertices, and patch counts of shapes whose angles are known
// (inkray-bench-meshes times them on a million triangles).
#include "core/geometry/mesh_features.h"
#include "core/geometry/obj_loader.h"
#include "core/geometry/triangle_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <set>
#include <string>

namespace inkray {
namespace {

const std::filesystem::path kSource = INKRAY_SOURCE_DIR;

TriangleMeshData load(const std::filesystem::path& file) {
  std::string error;
  auto mesh = load_obj(file, &error);
  EXPECT_TRUE(mesh) << error;
  return mesh ? *mesh : TriangleMeshData{};
}

MeshFeatures features_of(const TriangleMeshData& m) { return find_feature_edges(m.positions, m.indices); }
MeshFeatures features_of(const TriangleMesh& m) {
  return find_feature_edges(std::span(m.positions.data(), m.vertex_count()), m.indices);
}

size_t patch_count(const MeshFeatures& f, float threshold) {
  const std::vector<uint32_t> patches = smooth_patches(f, threshold);
  EXPECT_EQ(patches.size(), f.triangles);
  return std::set<uint32_t>(patches.begin(), patches.end()).size();
}

TEST(MeshFeatures, BevelledCubePatches) {
  // 6 faces, 12 chamfers (45 degrees to the faces) and 8 corner triangles (35.26
  // degrees to the chamfers): 26 flat regions.
  const MeshFeatures f = features_of(load(kSource / "tests/data/meshes/bevel_cube.obj"));
  EXPECT_EQ(f.triangles, 44u);
  EXPECT_EQ(f.edges.size(), 66u) << "closed: every edge shared by two triangles";
  EXPECT_EQ(patch_count(f, 0.f), 26u) << "the two triangles of a flat face meet at 0 degrees";
  EXPECT_EQ(patch_count(f, 30.f), 26u);
  EXPECT_EQ(patch_count(f, 40.f), 7u) << "the chamfers and corners join into one band; the faces stay";
  EXPECT_EQ(patch_count(f, 60.f), 1u);
}

TEST(MeshFeatures, PatchIdsCountFromZeroByFirstTriangle) {
  const MeshFeatures f = features_of(load(kSource / "tests/data/meshes/bevel_cube.obj"));
  const std::vector<uint32_t> patches = smooth_patches(f, 30.f);
  uint32_t next = 0;
  for (const uint32_t p : patches) {
    ASSERT_LE(p, next);
    if (p == next) ++next;
  }
  EXPECT_EQ(next, 26u);
}

TEST(MeshFeatures, SmoothSphereIsOnePatch) {
  const MeshFeatures f = features_of(load(kSource / "tests/data/meshes/tess_sphere.obj"));
  EXPECT_EQ(patch_count(f, 30.f), 1u);
  // Below the angles between rings (5.6 degrees), each planar quad of the 32 x 64
  // grid is a patch of its own, but near the poles, where neighbours in a ring meet
  // at under a degree.
  EXPECT_GT(patch_count(f, 1.f), 1500u);
}

TEST(MeshFeatures, EdgesJoinAcrossSplitVertices) {
  // cube.obj has a normal and uv per face corner: 24 vertices, no index shared
  // between faces. Its edges are still found, by position.
  const TriangleMeshData cube = load(kSource / "tests/data/meshes/cube.obj");
  ASSERT_EQ(cube.positions.size(), 24u);
  const MeshFeatures f = features_of(cube);
  EXPECT_EQ(f.edges.size(), 18u);
  EXPECT_EQ(patch_count(f, 89.f), 6u);
  EXPECT_EQ(patch_count(f, 91.f), 1u);
  for (const FeatureEdge& e : f.edges) EXPECT_TRUE(e.dihedral < 1e-3f || std::abs(e.dihedral - 90.f) < 1e-3f);
}

TEST(MeshFeatures, BoxesAndQuads) {
  const TriangleMesh box = make_box(Point3(0.f), Point3(1.f, 2.f, 3.f), Transform{});
  EXPECT_EQ(patch_count(features_of(box), 30.f), 6u);
  EXPECT_EQ(patch_count(features_of(box), 89.9f), 6u);
  EXPECT_EQ(patch_count(features_of(box), 90.1f), 1u);
  const TriangleMesh quad = make_quad(Point3(0.f), Vec3(1.f, 0.f, 0.f), Vec3(0.f, 1.f, 0.f), Transform{});
  EXPECT_EQ(patch_count(features_of(quad), 0.f), 1u);
}

TEST(MeshFeatures, NoisyScanBreaksIntoFewerPatchesAsTheThresholdRises) {
  const MeshFeatures f = features_of(load(kSource / "scenes/meshes/scan_noisy.obj"));
  size_t last = f.triangles + 1;
  std::string counts;
  for (const float threshold : {2.f, 5.f, 10.f, 20.f, 30.f, 45.f, 90.f}) {
    const size_t n = patch_count(f, threshold);
    counts += " " + std::to_string(n);
    EXPECT_LE(n, last) << "at " << threshold << " degrees";
    last = n;
  }
  EXPECT_GT(patch_count(f, 5.f), 100u) << counts;
  EXPECT_EQ(patch_count(f, 45.f), 1u) << counts;
}

TEST(MeshFeatures, DegenerateAndNonManifoldTriangles) {
  TriangleMeshData m;
  m.positions = {{0.f, 0.f, 0.f}, {1.f, 0.f, 0.f},     {0.f, 1.f, 0.f},
                 {2.f, 0.f, 0.f}, {0.5f, -0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}};
  m.indices = {0, 1, 2,   // a
               1, 0, 4,   // b, sharing 0-1 with a
               0, 1, 5,   // c, a third triangle on 0-1
               0, 3, 1};  // on a line: no area
  const MeshFeatures f = features_of(m);
  EXPECT_EQ(f.edges.size(), 6u) << "four triangles on one edge pair up every way";
  size_t infinite = 0;
  for (const FeatureEdge& e : f.edges) infinite += std::isinf(e.dihedral);
  EXPECT_EQ(infinite, 3u) << "every pair with the degenerate triangle";
  const std::vector<uint32_t> patches = smooth_patches(f, 180.f);
  EXPECT_EQ(patches[0], patches[1]);
  EXPECT_EQ(patches[0], patches[2]);
  EXPECT_NE(patches[3], patches[0]) << "a degenerate triangle is a patch of its own";
}

}  // namespace
}  // namespace inkray
