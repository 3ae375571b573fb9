// OBJ meshes: attributes, vertex splitting, triangulation of convex and concave
// polygons, and broken files that must fail with the file name and line.
#include "core/geometry/obj_loader.h"
#include "tests/support/damaged_text.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace inkray {
namespace {

namespace fs = std::filesystem;

const fs::path kMeshes = fs::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "meshes";

TriangleMeshData load_ok(const fs::path& file) {
  std::string error;
  std::optional<TriangleMeshData> mesh = load_obj(file, &error);
  EXPECT_TRUE(mesh.has_value()) << error;
  return mesh ? *mesh : TriangleMeshData{};
}

std::string load_error(const fs::path& file) {
  std::string error;
  EXPECT_FALSE(load_obj(file, &error).has_value()) << file;
  return error;
}

std::string parse_error(std::string_view text) {
  std::string error;
  EXPECT_FALSE(parse_obj(text, "mem.obj", &error).has_value()) << text;
  return error;
}

Vec3 triangle_normal(const TriangleMeshData& m, std::size_t t) {  // not normalised: length is twice the area
  const Point3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
               c = m.positions[m.indices[3 * t + 2]];
  return glm::cross(b - a, c - a);
}

void expect_valid_indices(const TriangleMeshData& m) {
  ASSERT_EQ(m.indices.size() % 3, 0u);
  for (uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
  if (!m.normals.empty()) {
    EXPECT_EQ(m.normals.size(), m.positions.size());
  }
  if (!m.uvs.empty()) {
    EXPECT_EQ(m.uvs.size(), m.positions.size());
  }
}

// A file that loads, with its indices checked.
TriangleMeshData load_valid(const fs::path& file) {
  const TriangleMeshData m = load_ok(file);
  expect_valid_indices(m);
  return m;
}

// How many indices, positions and normals (0: none) the mesh holds.
void expect_sizes(const TriangleMeshData& m, size_t indices, size_t positions, size_t normals) {
  EXPECT_EQ(m.indices.size(), indices);
  EXPECT_EQ(m.positions.size(), positions);
  EXPECT_EQ(m.normals.size(), normals);
}

TEST(ObjLoader, CubeWithNormalsAndUvs) {
  const TriangleMeshData m = load_valid(kMeshes / "cube.obj");  // its missing mtllib must not matter
  expect_sizes(m, 36, 24, 24);                                  // 8 corners split by 6 face normals
  EXPECT_EQ(m.uvs.size(), 24u);
  for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
    const Vec3 n = glm::normalize(triangle_normal(m, t));
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(glm::dot(n, m.normals[m.indices[3 * t + k]]), 0.99f) << "triangle " << t;
    }
  }
  for (const Vec2& uv : m.uvs) {
    EXPECT_TRUE(uv.x == 0.f || uv.x == 1.f);
    EXPECT_TRUE(uv.y == 0.f || uv.y == 1.f);
  }
}

TEST(ObjLoader, CubeWithoutAttributesMergesShapes) {
  const TriangleMeshData m = load_valid(kMeshes / "cube_positions.obj");
  expect_sizes(m, 36, 8, 0);
  EXPECT_TRUE(m.uvs.empty());
  float area = 0.f;
  for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
    const Vec3 n = triangle_normal(m, t);
    const Point3 centroid = (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
                             m.positions[m.indices[3 * t + 2]]) /
                            3.f;
    EXPECT_GT(glm::dot(n, centroid - Point3(0.5f)), 0.f) << "triangle " << t << " faces inwards";
    area += 0.5f * glm::length(n);
  }
  EXPECT_NEAR(area, 6.f, 1e-5f);
}

TEST(ObjLoader, ConvexPolygonIsTriangulated) {
  const TriangleMeshData m = load_valid(kMeshes / "pentagon.obj");
  expect_sizes(m, 9, 5, 5);
  float area = 0.f;
  for (std::size_t t = 0; t < 3; ++t) {
    EXPECT_GT(triangle_normal(m, t).z, 0.f);
    area += 0.5f * glm::length(triangle_normal(m, t));
  }
  EXPECT_NEAR(area, 2.5f * std::sin(2.f * kPi / 5.f), 1e-4f);
}

TEST(ObjLoader, ConcavePolygonIsTriangulatedWithoutOverlap) {
  const TriangleMeshData m = load_valid(kMeshes / "concave.obj");
  ASSERT_EQ(m.indices.size(), 12u);
  float area = 0.f;
  for (std::size_t t = 0; t < 4; ++t) {
    EXPECT_GT(triangle_normal(m, t).z, 0.f) << "triangle " << t << " is flipped";
    area += 0.5f * glm::length(triangle_normal(m, t));
  }
  EXPECT_NEAR(area, 3.f, 1e-5f);  // overlapping triangles would cover more
}

TEST(ObjLoader, PartialAttributesAreDropped) {
  const TriangleMeshData m = load_valid(kMeshes / "mixed_attributes.obj");
  expect_sizes(m, 6, 4, 0);
}

TEST(ObjLoader, VerticesSplitOnlyWhereAttributesDiffer) {
  const char* text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
      "f 1/1 2/2 3/3\n"
      "f 2/2 4/4 3/5\n";  // position 3 again, with a different uv: split; position 2 shared: not split
  std::string error;
  const std::optional<TriangleMeshData> m = parse_obj(text, "split.obj", &error);
  ASSERT_TRUE(m) << error;
  expect_valid_indices(*m);
  EXPECT_EQ(m->positions.size(), 5u);
  EXPECT_EQ(m->indices[1], m->indices[3]);
  EXPECT_NE(m->indices[2], m->indices[5]);
  EXPECT_EQ(m->positions[m->indices[2]], m->positions[m->indices[5]]);
  EXPECT_EQ(m->uvs[m->indices[5]], Vec2(0.5f));
}

TEST(ObjLoader, LineEndingsAgree) {
  const std::string unix_text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const std::string newline : {"\r\n", "\r"}) {
    std::string text = unix_text;
    for (std::size_t at = text.find('\n'); at != std::string::npos;
         at = text.find('\n', at + newline.size())) {
      text.replace(at, 1, newline);
    }
    std::string error;
    const std::optional<TriangleMeshData> m = parse_obj(text, "crlf.obj", &error);
    ASSERT_TRUE(m) << error;
    EXPECT_EQ(m->indices.size(), 3u);
  }
  EXPECT_NE(parse_error("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 4\r\n").find("mem.obj: line 4: "),
            std::string::npos);
}

TEST(ObjLoader, BrokenFilesNameTheFileAndLine) {
  std::string error = load_error(kMeshes / "broken_index.obj");
  EXPECT_NE(error.find("broken_index.obj: line 5: position index 9 is out of range"), std::string::npos)
      << error;
  error = load_error(kMeshes / "broken_garbage.obj");
  EXPECT_NE(error.find("broken_garbage.obj: line 2: expected 3 coordinates"), std::string::npos) << error;
  EXPECT_NE(error.find("\"abc\""), std::string::npos) << error;
  error = load_error(kMeshes / "broken_statement.obj");
  EXPECT_NE(error.find("broken_statement.obj: line 4: unknown statement \"this\""), std::string::npos)
      << error;
}

TEST(ObjLoader, EmptyAndMissingFilesFailCleanly) {
  std::string error = load_error(kMeshes / "empty.obj");
  EXPECT_NE(error.find("empty.obj: no faces"), std::string::npos) << error;
  error = load_error(kMeshes / "no_such_mesh.obj");
  EXPECT_NE(error.find("no_such_mesh.obj: cannot open the mesh: no such file"), std::string::npos) << error;
  error = load_error(kMeshes);
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  EXPECT_FALSE(parse_obj("", "blank.obj", nullptr).has_value());  // a null error pointer is allowed
}

TEST(ObjLoader, EveryBadLineIsCaught) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  std::string big_face = "f";
  for (int i = 0; i < 300; ++i) big_face += " 1";
  const struct {
    std::string line;
    std::string expected;
  } cases[] = {
      {"f 0 1 2", "index 0 is invalid"},
      {"f 1 2", "at least 3 vertices"},
      {"f -4 1 2", "position index -4 is out of range"},
      {"f 1/2 2/1 3/1", "texture coordinate index 2 is out of range (1 defined so far)"},
      {"f 1//2 2//1 3//1", "normal index 2 is out of range"},
      {"f 1/ 2 3", "expected a face vertex like"},
      {"f 1//1/1 2 3", "expected a face vertex like"},
      {"f a b c", "expected an integer position index, got \"a\""},
      {"f 1.5 2 3", "expected an integer position index"},
      {"v 1 2", "expected 3 coordinates"},
      {"v 1 2 nan", "got \"nan\""},
      {"v 1 2 1e39", "got \"1e39\""},
      {"vn 0 1", "expected 3 normal components"},
      {"vt", "expected 1 to 3 texture coordinates"},
      {"t 1000000000/0/0", "unknown statement \"t\""},
      {std::string("\x89PNG\x01\x02", 6), "unknown statement \"\\x89PNG\\x01\\x02\""},
      {big_face, "a face with 300 vertices (at most 256"},
  };
  for (const auto& c : cases) {
    const std::string error = parse_error(triangle + c.line + "\nf 1 2 3\n");
    EXPECT_EQ(error.rfind("mem.obj: line 6: ", 0), 0u) << error;
    EXPECT_NE(error.find(c.expected), std::string::npos) << error;
  }
}

TEST(ObjLoader, CommentsBlankLinesAndOtherStatementsAreAccepted) {
  const char* text =
      "# exported by hand\n\n   \t\nmtllib x.mtl\no thing\ng a b\ns 1\nusemtl red\n"
      "v 0 0 0 # trailing comment\nv 1 0 0 1\nv 0 1 0 0.5 0.5 0.5\nvt 0.5\nl 1 2\np 3\nf 1/1 2/1 3/1\n";
  std::string error;
  const std::optional<TriangleMeshData> m = parse_obj(text, "misc.obj", &error);
  ASSERT_TRUE(m) << error;
  EXPECT_EQ(m->indices.size(), 3u);
  EXPECT_EQ(m->uvs.size(), 3u);
}

// Random edits of a valid mesh must never crash the loader, and whatever it accepts
// must be a consistent mesh.
TEST(ObjLoader, MutatedFilesNeverCrash) {
  std::ifstream in(kMeshes / "cube.obj");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string original = ss.str();
  std::mt19937 rng(7);
  // The NUL ends the literal: the alphabet is the characters before it.
  const testing::TextDamage damage{
      .alphabet = "0123456789-/ .fvtn#\n\x00\xff", .max_erase = 8, .max_copy = 24};
  for (int iteration = 0; iteration < 3000; ++iteration) {
    const std::string text = testing::damaged(original, rng, damage);
    std::string error;
    std::optional<TriangleMeshData> m;
    ASSERT_NO_THROW(m = parse_obj(text, "mutated.obj", &error));
    if (m) {
      expect_valid_indices(*m);
    } else {
      EXPECT_EQ(error.rfind("mutated.obj: ", 0), 0u) << error;
    }
  }
}

}  // namespace
}  // namespace inkray
