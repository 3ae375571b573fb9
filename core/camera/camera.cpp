#include "core/camera/camera.h"

#include "core/sampling/warp.h"

#include <cmath>

namespace inkray {

Camera::Camera(const CameraParams& params, int width, int height)
    : width_(float(width)), height_(float(height)) {
  view_ = make_view(params);
}

Camera::Camera(const CameraParams& params, const CameraParams& open, const CameraParams& close, int width,
               int height, float frame_time)
    : Camera(params, width, height) {
  frame_time_ = glm::clamp(frame_time, 0.f, 1.f);
  if (open == close) return;
  // A focus distance of 0 means "on look_at": resolved at each end, so the focus
  // follows the target between them.
  std::array<CameraParams, 2> ends = {open, close};
  for (CameraParams& end : ends)
    if (!(end.focus_distance > 0.f)) end.focus_distance = glm::length(end.look_at - end.look_from);
  motion_ = ends;
}

Camera::View Camera::make_view(const CameraParams& params) const {
  View view;
  view.origin = params.look_from;
  view.w = glm::normalize(params.look_at - params.look_from);
  view.u = glm::normalize(glm::cross(view.w, params.up));
  view.v = glm::cross(view.u, view.w);
  view.half_height = std::tan(glm::radians(params.vfov) * 0.5f);
  view.half_width = view.half_height * width_ / height_;
  view.lens_radius = params.aperture * 0.5f;
  view.focus_distance =
      params.focus_distance > 0.f ? params.focus_distance : glm::length(params.look_at - params.look_from);
  return view;
}

// Inline: a still camera's ray costs what it did before cameras could move.
inline Ray Camera::ray_from(const View& view, Vec2 film, Vec2 lens, float time) const {
  const float sx = (2.f * film.x / width_ - 1.f) * view.half_width;
  const float sy = (1.f - 2.f * film.y / height_) * view.half_height;
  const Vec3 dir = view.w + sx * view.u + sy * view.v;  // reaches the plane at distance 1
  if (view.lens_radius <= 0.f) return {view.origin, glm::normalize(dir), time};
  const Vec2 l = view.lens_radius * sample_uniform_disk_concentric(lens);
  const Point3 lens_point = view.origin + l.x * view.u + l.y * view.v;
  const Point3 focus_point = view.origin + view.focus_distance * dir;
  return {lens_point, glm::normalize(focus_point - lens_point), time};
}

Ray Camera::generate_ray(Vec2 film, Vec2 lens, float time) const {
  if (motion_) [[unlikely]]
    return moving_ray(film, lens, time);
  return ray_from(view_, film, lens, time);
}

Camera::View Camera::view_at(float time) const {
  const CameraParams& a = (*motion_)[0];
  const CameraParams& b = (*motion_)[1];
  CameraParams now;
  now.look_from = glm::mix(a.look_from, b.look_from, time);
  now.look_at = glm::mix(a.look_at, b.look_at, time);
  now.up = glm::mix(a.up, b.up, time);
  now.vfov = glm::mix(a.vfov, b.vfov, time);
  now.aperture = glm::mix(a.aperture, b.aperture, time);
  now.focus_distance = glm::mix(a.focus_distance, b.focus_distance, time);
  return make_view(now);
}

Ray Camera::moving_ray(Vec2 film, Vec2 lens, float time) const {
  return ray_from(view_at(time), film, lens, time);
}

bool Camera::project(const Point3& p, Vec2* film) const {
  const Vec3 d = p - view_.origin;
  const float z = glm::dot(d, view_.w);
  if (z <= 0.f) return false;
  const float sx = glm::dot(d, view_.u) / z / view_.half_width,
              sy = glm::dot(d, view_.v) / z / view_.half_height;
  *film = {(sx + 1.f) * 0.5f * width_, (1.f - sy) * 0.5f * height_};
  return true;
}

}  // namespace inkray
