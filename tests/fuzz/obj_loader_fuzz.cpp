// Fuzz harness for the OBJ loader: parse_obj must never throw, and a mesh it returns
// must be safe to hand to Embree (whole triangles, indices in range, finite values).
#include "core/geometry/obj_loader.h"
#include "tests/fuzz/fuzz_targets.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {
namespace {

template <class Vector>
bool all_finite(const std::vector<Vector>& values) {
  for (const Vector& v : values)
    for (int i = 0; i < Vector::length(); ++i)
      if (!std::isfinite(v[i])) return false;
  return true;
}

}  // namespace

int fuzz_obj_loader(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string error;
  const std::optional<TriangleMeshData> mesh = parse_obj(text, "fuzz.obj", &error);
  if (!mesh) {
    if (error.empty()) fuzz_fail("parse_obj failed without an error message");
    return 0;
  }
  if (mesh->indices.empty() || mesh->indices.size() % 3 != 0)
    fuzz_fail("index count " + std::to_string(mesh->indices.size()) + " is not whole triangles");
  for (const std::uint32_t index : mesh->indices)
    if (index >= mesh->positions.size())
      fuzz_fail("index " + std::to_string(index) + " is past " + std::to_string(mesh->positions.size()) +
                " positions");
  if (!mesh->normals.empty() && mesh->normals.size() != mesh->positions.size())
    fuzz_fail("normals and positions differ in count");
  if (!mesh->uvs.empty() && mesh->uvs.size() != mesh->positions.size())
    fuzz_fail("uvs and positions differ in count");
  if (!all_finite(mesh->positions) || !all_finite(mesh->normals) || !all_finite(mesh->uvs))
    fuzz_fail("a vertex attribute is not finite");
  return 0;
}

}  // namespace inkray
