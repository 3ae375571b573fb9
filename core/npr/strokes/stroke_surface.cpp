// Dispatch between the analytic sphere and mesh surfaces, and the measures of
// size and coordinate magnitude that stroke offsets derive from.
#include "core/npr/strokes/stroke_surface.h"

#include <cmath>

namespace inkray {
namespace {

void shape_bounds(const Shape& shape, Point3* lo, Point3* hi) {
  if (const auto* sphere = std::get_if<Sphere>(&shape)) {
    sphere->bounds(lo, hi);
    return;
  }
  const auto& mesh = std::get<TriangleMesh>(shape);
  *lo = Point3(kInfinity);
  *hi = Point3(-kInfinity);
  for (size_t i = 0; i < mesh.vertex_count(); ++i) {
    *lo = glm::min(*lo, mesh.positions[i]);
    *hi = glm::max(*hi, mesh.positions[i]);
  }
}

}  // namespace

std::optional<StrokeSurface> StrokeSurface::from_shape(const Shape& shape, std::string* error) {
  Point3 lo, hi;
  shape_bounds(shape, &lo, &hi);
  const float size = glm::length(hi - lo);
  const float magnitude = max_component(glm::max(glm::abs(lo), glm::abs(hi)));
  std::optional<StrokeSurface> surface;
  if (const auto* sphere = std::get_if<Sphere>(&shape)) {
    surface = StrokeSurface(SphereSurface(*sphere), size, magnitude);
  } else {
    const auto& mesh = std::get<TriangleMesh>(shape);
    if (mesh.triangle_count() == 0) {
      *error = "the object has no triangles to grow strokes on";
      return std::nullopt;
    }
    surface = StrokeSurface(MeshSurface(mesh), size, magnitude);
  }
  const double area = surface->area();
  if (!(area > 0.0) || !std::isfinite(area) || !std::isfinite(size)) {
    *error = "the object has zero area (or a non-finite size): there is no surface to grow strokes on";
    return std::nullopt;
  }
  return surface;
}

double StrokeSurface::area() const {
  return std::visit([](const auto& s) { return s.area(); }, surface_);
}

SurfacePoint StrokeSurface::sample(uint32_t seed, uint32_t index) const {
  return std::visit([&](const auto& s) { return s.sample(seed, index); }, surface_);
}

Point3 StrokeSurface::sample_position(uint32_t seed, uint32_t index) const {
  return std::visit([&](const auto& s) { return s.sample_position(seed, index); }, surface_);
}

SurfacePoint StrokeSurface::project(const Point3& p, float near) const {
  return std::visit([&](const auto& s) { return s.project(p, near); }, surface_);
}

}  // namespace inkray
