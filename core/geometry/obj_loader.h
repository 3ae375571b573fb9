// Wavefront OBJ meshes for MeshDesc shapes: every shape in the file merged into one
// indexed triangle mesh. Each line is checked before tinyobjloader parses the file, so
// a broken mesh gives "<file>: line N: <what was expected>" instead of a wrong mesh.
#pragma once

#include "core/math/types.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// Ear clipping costs up to cubic time in a face's size; real files stay far below this.
inline constexpr std::size_t kMaxObjFaceVertices = 256;

struct TriangleMeshData {  // indexed triangles, attributes per vertex
  std::vector<Point3> positions;
  std::vector<Normal3> normals;   // empty unless every face vertex has a normal
  std::vector<Vec2> uvs;          // empty unless every face vertex has texture coordinates
  std::vector<uint32_t> indices;  // 3 per triangle
};

// Polygons are triangulated; a vertex is split where a position is used with different
// normals or uvs. On failure returns nullopt and sets *error to
// "<file>: line N: <what was expected>" where a line is to blame, else "<file>: <reason>".
std::optional<TriangleMeshData> load_obj(const std::filesystem::path& file, std::string* error);

// The same for text already in memory; file_label starts the error message.
std::optional<TriangleMeshData> parse_obj(std::string_view text, std::string_view file_label,
                                          std::string* error);

}  // namespace inkray
