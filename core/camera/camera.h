// Pinhole and thin-lens camera: maps a film position and a lens sample to a
// world-space ray. It only generates rays; integration and film live elsewhere.
#pragma once

#include "core/geometry/ray.h"
#include "core/document/desc.h"

namespace inkray {

class Camera {
 public:
  Camera() = default;
  Camera(const CameraDesc& desc, int width, int height);

  // film: continuous pixel coordinates, (0,0) top-left, (width,height) bottom-right.
  // lens: a 2D sample in [0,1)^2, ignored by a pinhole.
  Ray generate_ray(Vec2 film, Vec2 lens) const;
  // The film position a world point projects to (pinhole projection); false if behind.
  bool project(const Point3& p, Vec2* film) const;

  // Film pixels spanned by a world length at a distance along the view axis.
  float world_to_pixels(float length, float distance) const {
    return length * height_ / (2.f * half_height_ * std::max(distance, 1e-20f));
  }
  float image_height() const { return height_; }

  const Point3& origin() const { return origin_; }
  const Vec3& forward() const { return w_; }

 private:
  Point3 origin_{0.f};
  Vec3 u_{1.f, 0.f, 0.f}, v_{0.f, 1.f, 0.f}, w_{0.f, 0.f, -1.f};  // right, up, forward
  float half_height_ = 1.f, half_width_ = 1.f;
  float lens_radius_ = 0.f;
  float focus_distance_ = 1.f;
  float width_ = 1.f, height_ = 1.f;
};

}  // namespace inkray
