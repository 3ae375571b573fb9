// Auto smooth (core/geometry/mesh_normals.h) on meshes from scripts/make_test_meshes.py:
// a tessellated sphere against its analytic normals, a bevelled cube whose edges are
// all sharper than 30 degrees, normals in the file left alone, and broken geometry
// that must still give finite unit normals.
#include "core/geometry/mesh_normals.h"
#include "core/geometry/mesh_features.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace inkray {
namespace {

const std::filesystem::path kMeshes = INKRAY_SOURCE_DIR "/tests/data/meshes";

// The mesh read, or (with the test failed) an empty one.
TriangleMeshData expect_mesh(const std::optional<TriangleMeshData>& mesh, const std::string& error) {
  EXPECT_TRUE(mesh) << error;
  return mesh ? *mesh : TriangleMeshData{};
}
TriangleMeshData load(const std::string& name) {
  std::string error;
  return expect_mesh(load_obj(kMeshes / name, &error), error);
}
TriangleMeshData parse(const std::string& text, const std::string& name) {
  std::string error;
  return expect_mesh(parse_obj(text, name, &error), error);
}

float angle_degrees(const Vec3& a, const Vec3& b) {
  return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

Normal3 facet(const TriangleMeshData& m, size_t t) {
  return facet_normal(m.positions[m.indices[3 * t]], m.positions[m.indices[3 * t + 1]],
                      m.positions[m.indices[3 * t + 2]]);
}

void expect_unit_normals(const TriangleMeshData& m) {
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const Normal3& n : m.normals) {
    ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    EXPECT_NEAR(glm::length(n), 1.f, 1e-5f);
  }
}

// Triangles and positions survive smoothing: the same corners in the same order.
void expect_same_triangles(const TriangleMeshData& before, const TriangleMeshData& after) {
  ASSERT_EQ(before.indices.size(), after.indices.size());
  for (size_t c = 0; c < before.indices.size(); ++c)
    ASSERT_EQ(before.positions[before.indices[c]], after.positions[after.indices[c]]) << "corner " << c;
}

struct Errors {
  double mean = 0.0, max = 0.0;
};

// Angle between each vertex normal and the unit sphere's normal there, in degrees.
Errors sphere_errors(const TriangleMeshData& m) {
  Errors e;
  for (size_t v = 0; v < m.positions.size(); ++v) {
    const double a = angle_degrees(m.normals[v], glm::normalize(m.positions[v]));
    e.mean += a;
    e.max = std::max(e.max, a);
  }
  e.mean /= double(m.positions.size());
  return e;
}

TEST(AutoSmooth, TessellatedSphereMatchesTheAnalyticNormal) {
  const TriangleMeshData sphere = load("tess_sphere.obj");
  ASSERT_TRUE(sphere.normals.empty());
  for (const float angle : {30.f, 180.f}) {
    SCOPED_TRACE(angle);
    const TriangleMeshData smooth = auto_smooth(sphere, angle);
    expect_unit_normals(smooth);
    expect_same_triangles(sphere, smooth);
    // Facets meet at under 6 degrees: nothing splits, one normal per position.
    EXPECT_EQ(smooth.positions.size(), sphere.positions.size());
    const Errors e = sphere_errors(smooth);
    std::printf(
        "[ measured ] smooth angle %g: vertex normals off the sphere's by %.4f degrees on average, %.4f at "
        "most\n",
        double(angle), e.mean, e.max);
    // Measured 0.055 on average and 0.088 at most; the facets themselves are off by
    // up to about 2.8 degrees (half the angle between rings).
    EXPECT_LT(e.mean, 0.2);
    EXPECT_LT(e.max, 0.5);
  }
}

TEST(AutoSmooth, ZeroKeepsTheFacets) {
  const TriangleMeshData sphere = load("tess_sphere.obj");
  EXPECT_FALSE(needs_auto_smooth(sphere, 0.f));
  const TriangleMeshData flat = auto_smooth(sphere, 0.f);
  EXPECT_TRUE(flat.normals.empty()) << "no normals: the renderer shades each facet flat";
  EXPECT_EQ(flat.indices, sphere.indices);
}

// bevel_cube.obj: 6 faces, 12 chamfers at 45 degrees to them, 8 corner triangles at
// 35.26 degrees to the chamfers; its 24 positions are the faces' corners.
TEST(AutoSmooth, BevelledCubeStaysFacetedBelowItsAngles) {
  const TriangleMeshData cube = load("bevel_cube.obj");
  ASSERT_EQ(cube.positions.size(), 24u);
  const TriangleMeshData smooth = auto_smooth(cube, 30.f);
  expect_unit_normals(smooth);
  expect_same_triangles(cube, smooth);
  // Each position splits into one vertex per region around it: a face, two
  // chamfers and a corner triangle.
  EXPECT_EQ(smooth.positions.size(), 24u * 4u);
  for (size_t c = 0; c < smooth.indices.size(); ++c)
    EXPECT_LT(angle_degrees(smooth.normals[smooth.indices[c]], facet(smooth, c / 3)), 1e-3f)
        << "corner " << c;
}

TEST(AutoSmooth, BevelledCubeBlendsFaceAndChamfersAboveTheirAngle) {
  const TriangleMeshData cube = load("bevel_cube.obj");
  const TriangleMeshData smooth = auto_smooth(cube, 60.f);
  expect_unit_normals(smooth);
  expect_same_triangles(cube, smooth);
  ASSERT_EQ(smooth.positions.size(), 24u) << "every edge is smooth at 60 degrees: one normal per position";
  for (size_t v = 0; v < smooth.positions.size(); ++v) {
    const Point3 p = smooth.positions[v];
    // The face this corner belongs to, its two chamfers and the corner triangle, weighted
    // by their corner angles: 90 degrees for the face's and chamfers' rectangles (however
    // each is split into triangles), 60 for the equilateral corner triangle.
    int a = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(p[k]) > std::abs(p[a])) a = k;
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const Vec3 s = glm::sign(p);
    Vec3 face(0.f), along_b(0.f), along_c(0.f);
    face[a] = s[a];
    along_b[b] = s[b];
    along_c[c] = s[c];
    const Vec3 expected = glm::normalize(90.f * face + 90.f * glm::normalize(face + along_b) +
                                         90.f * glm::normalize(face + along_c) + 60.f * glm::normalize(s));
    EXPECT_LT(angle_degrees(smooth.normals[v], expected), 1e-3f)
        << "vertex at " << p.x << " " << p.y << " " << p.z;
    EXPECT_GT(angle_degrees(smooth.normals[v], face), 10.f) << "pulled towards the chamfers";
  }
}

TEST(AutoSmooth, NormalsInTheFileAreUsedAsGiven) {
  // Deliberately odd normals: smoothing would replace them with (0, 0, 1).
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vn 0.6 0 0.8\nvn 0 0.6 0.8\nvn 0 0 1\n"
      "f 1//1 2//2 3//3\nf 2//2 4//1 3//3\n";
  const TriangleMeshData mesh = parse(text, "given.obj");
  EXPECT_FALSE(needs_auto_smooth(mesh, 30.f));
  for (const float angle : {0.f, 30.f, 180.f}) {
    const TriangleMeshData out = auto_smooth(mesh, angle);
    EXPECT_EQ(out.positions, mesh.positions);
    EXPECT_EQ(out.normals, mesh.normals);
    EXPECT_EQ(out.indices, mesh.indices);
  }
  const TriangleMeshData cube = load("cube.obj");  // a normal per face corner
  EXPECT_EQ(auto_smooth(cube, 180.f).normals, cube.normals);
}

TEST(AutoSmooth, UvSeamsSplitVerticesButNotNormals) {
  // Two triangles of one plane whose shared edge has different uvs on each side.
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.2\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\nvt 0.7 0.7\nvt 1 1\n"
      "f 1/1 2/2 3/3\nf 2/4 4/6 3/5\n";
  const TriangleMeshData mesh = parse(text, "seam.obj");
  const TriangleMeshData smooth = auto_smooth(mesh, 30.f);
  ASSERT_EQ(smooth.uvs.size(), smooth.positions.size());
  EXPECT_EQ(smooth.positions.size(), mesh.positions.size()) << "the uv split is kept, nothing more";
  // The two vertices at (1, 0, 0), one per side of the seam, share one normal.
  for (size_t i = 0; i < smooth.positions.size(); ++i)
    for (size_t j = i + 1; j < smooth.positions.size(); ++j)
      if (smooth.positions[i] == smooth.positions[j]) {
        EXPECT_EQ(smooth.normals[i], smooth.normals[j]);
      }
  for (size_t c = 0; c < smooth.indices.size(); ++c)
    EXPECT_EQ(smooth.uvs[smooth.indices[c]], mesh.uvs[mesh.indices[c]]);
}

TEST(AutoSmooth, BrokenGeometryGivesFiniteNormals) {
  TriangleMeshData m;
  m.positions = {
      {0.f, 0.f, 0.f},   {1.f, 0.f, 0.f},    {0.f, 1.f, 0.f},  // a good triangle
      {2.f, 0.f, 0.f},                                         // collinear with 0 and 1
      {0.5f, 0.5f, 1.f}, {0.5f, 0.5f, -1.f},  // a third and fourth page on edge 0-1 (non-manifold)
      {5.f, 5.f, 5.f},                        // used by degenerate triangles only
      {7.f, 0.f, 0.f},   {8.f, 0.f, 0.f},    {7.f, 1.f, 0.f},  // a sheet, folded flat onto itself below
  };
  m.indices = {
      0, 1, 2,  // good
      0, 3, 1,  // zero area: on a line, sharing edge 0-1
      0, 1, 4,  // non-manifold pages on edge 0-1
      1, 0, 5,  //
      6, 6, 2,  // two corners at one vertex
      6, 6, 6,  // a point
      7, 8, 9,  // the same triangle both ways round: normals cancel at 180 degrees
      7, 9, 8,  //
  };
  for (const float angle : {1.f, 30.f, 90.f, 180.f}) {
    SCOPED_TRACE(angle);
    const TriangleMeshData smooth = auto_smooth(m, angle);
    expect_unit_normals(smooth);
    expect_same_triangles(m, smooth);
  }
}

}  // namespace
}  // namespace inkray
