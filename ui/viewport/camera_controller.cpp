#include "ui/viewport/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

constexpr float kMinDistance = 1e-3f;
constexpr float kMaxPitch = 1.5533f;  // 89 degrees

Vec3 safe_up(const CameraDesc& c) {
  const float len = glm::length(c.up);
  return len > 0.f ? c.up / len : Vec3(0.f, 1.f, 0.f);
}

}  // namespace

CameraDesc orbit(const CameraDesc& camera, float yaw, float pitch) {
  CameraDesc c = camera;
  const Vec3 up = safe_up(c);
  Vec3 offset = c.look_from - c.look_at;
  const float distance = std::max(glm::length(offset), kMinDistance);
  const Vec3 dir = offset / distance;
  // Angles relative to up: elevation from the equator and azimuth around up.
  const float elevation = std::asin(std::clamp(glm::dot(dir, up), -1.f, 1.f));
  Vec3 flat = dir - up * glm::dot(dir, up);
  if (glm::length(flat) < 1e-6f)
    flat = std::abs(up.x) < 0.9f ? glm::cross(up, Vec3(1, 0, 0)) : glm::cross(up, Vec3(0, 0, 1));
  flat = glm::normalize(flat);
  const Vec3 side = glm::normalize(glm::cross(up, flat));
  const float new_elevation = std::clamp(elevation + pitch, -kMaxPitch, kMaxPitch);
  const Vec3 rotated_flat = flat * std::cos(yaw) + side * std::sin(yaw);
  const Vec3 new_dir = rotated_flat * std::cos(new_elevation) + up * std::sin(new_elevation);
  c.look_from = c.look_at + new_dir * distance;
  return c;
}

CameraDesc pan(const CameraDesc& camera, float dx, float dy, float image_height) {
  CameraDesc c = camera;
  const Vec3 forward_raw = c.look_at - c.look_from;
  const float distance = std::max(glm::length(forward_raw), kMinDistance);
  const Vec3 forward = forward_raw / distance;
  const Vec3 right = glm::normalize(glm::cross(forward, safe_up(c)));
  const Vec3 up = glm::cross(right, forward);
  const float world_per_pixel =
      2.f * distance * std::tan(glm::radians(c.vfov) * 0.5f) / std::max(image_height, 1.f);
  // Dragging right moves the scene right: the camera moves left.
  const Vec3 shift = (-dx * right + dy * up) * world_per_pixel;
  c.look_from += shift;
  c.look_at += shift;
  return c;
}

CameraDesc dolly(const CameraDesc& camera, float factor) {
  CameraDesc c = camera;
  const Vec3 offset = c.look_from - c.look_at;
  const float distance = glm::length(offset);
  if (distance <= 0.f || !(factor > 0.f)) return c;
  const float new_distance = std::max(distance * factor, kMinDistance);
  c.look_from = c.look_at + offset * (new_distance / distance);
  return c;
}

CameraDesc frame_sphere(const CameraDesc& camera, const Point3& center, float radius) {
  CameraDesc c = camera;
  Vec3 dir = c.look_from - c.look_at;
  dir = glm::length(dir) > 0.f ? glm::normalize(dir) : Vec3(0.f, 0.f, 1.f);
  const float half_fov = glm::radians(std::clamp(c.vfov, 1.f, 170.f)) * 0.5f;
  const float distance = std::max(radius, kMinDistance) / std::sin(half_fov) * 1.1f;  // a margin around it
  c.look_at = center;
  c.look_from = center + dir * distance;
  return c;
}

CameraDesc focus_at(const CameraDesc& camera, float distance) {
  CameraDesc c = camera;
  c.focus_distance = std::max(distance, 0.f);
  return c;
}

CameraDesc CameraController::wheel(const CameraDesc& c, float steps) const {
  return dolly(c, std::pow(dolly_per_wheel_step, steps));
}

CameraDesc CameraController::drag_dolly(const CameraDesc& c, float dy) const {
  return dolly(c, std::exp(dy * dolly_per_pixel));
}

}  // namespace inkray
