#include "core/camera/camera.h"

#include "core/sampling/warp.h"

#include <cmath>

namespace inkray {

Camera::Camera(const CameraDesc& desc, int width, int height)
    : origin_(desc.look_from), width_(float(width)), height_(float(height)) {
  w_ = glm::normalize(desc.look_at - desc.look_from);
  u_ = glm::normalize(glm::cross(w_, desc.up));
  v_ = glm::cross(u_, w_);
  half_height_ = std::tan(glm::radians(desc.vfov) * 0.5f);
  half_width_ = half_height_ * width_ / height_;
  lens_radius_ = desc.aperture * 0.5f;
  focus_distance_ = desc.focus_distance > 0.f ? desc.focus_distance : glm::length(desc.look_at - desc.look_from);
}

Ray Camera::generate_ray(Vec2 film, Vec2 lens) const {
  const float sx = (2.f * film.x / width_ - 1.f) * half_width_;
  const float sy = (1.f - 2.f * film.y / height_) * half_height_;
  const Vec3 dir = w_ + sx * u_ + sy * v_;  // reaches the plane at distance 1
  if (lens_radius_ <= 0.f) return {origin_, glm::normalize(dir)};
  const Vec2 l = lens_radius_ * sample_uniform_disk_concentric(lens);
  const Point3 lens_point = origin_ + l.x * u_ + l.y * v_;
  const Point3 focus_point = origin_ + focus_distance_ * dir;
  return {lens_point, glm::normalize(focus_point - lens_point)};
}

bool Camera::project(const Point3& p, Vec2* film) const {
  const Vec3 d = p - origin_;
  const float z = glm::dot(d, w_);
  if (z <= 0.f) return false;
  const float sx = glm::dot(d, u_) / z / half_width_, sy = glm::dot(d, v_) / z / half_height_;
  *film = {(sx + 1.f) * 0.5f * width_, (1.f - sy) * 0.5f * height_};
  return true;
}

}  // namespace inkray
