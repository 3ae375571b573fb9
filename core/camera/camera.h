// Pinhole and thin-lens camera: maps a film position, a lens sample and an
// instant of the shutter to a world-space ray. It only generates rays;
// integration and film live elsewhere.
#pragma once

#include "core/camera/camera_params.h"
#include "core/geometry/ray.h"

#include <array>
#include <optional>

namespace inkray {

class Camera {
 public:
  Camera() = default;
  Camera(const CameraParams& params, int width, int height);
  // A camera that moves while the shutter is open: as `open` at time 0 and as
  // `close` at time 1, its parameters (look_from, look_at, up, vfov, aperture and
  // focus distance) interpolated linearly between (docs/architecture.md, "Motion
  // blur"). `params`, the camera at the frame, answers everything but generate_ray;
  // `frame_time` is the frame's own instant in the shutter.
  Camera(const CameraParams& params, const CameraParams& open, const CameraParams& close, int width,
         int height, float frame_time = 0.f);

  // film: continuous pixel coordinates, (0,0) top-left, (width,height) bottom-right.
  // lens: a 2D sample in [0,1)^2, ignored by a pinhole.
  // time: the instant of the shutter in [0,1), which the ray carries.
  Ray generate_ray(Vec2 film, Vec2 lens, float time) const;
  // The ray at the frame's own instant, which sees what a still of the frame shows
  // (picking, tools); 0 without motion blur.
  Ray generate_ray(Vec2 film, Vec2 lens) const { return generate_ray(film, lens, frame_time_); }
  // The film position a world point projects to (pinhole projection); false if behind.
  bool project(const Point3& p, Vec2* film) const;

  // Film pixels spanned by a world length at a distance along the view axis.
  float world_to_pixels(float length, float distance) const {
    return length * height_ / (2.f * view_.half_height * std::max(distance, 1e-20f));
  }
  float image_height() const { return height_; }
  // Whether it moves while the shutter is open.
  bool moves() const { return motion_.has_value(); }

  const Point3& origin() const { return view_.origin; }
  const Vec3& forward() const { return view_.w; }

 private:
  // Where the camera stands and how it sees, at one instant.
  struct View {
    Point3 origin{0.f};
    Vec3 u{1.f, 0.f, 0.f}, v{0.f, 1.f, 0.f}, w{0.f, 0.f, -1.f};  // right, up, forward
    float half_height = 1.f, half_width = 1.f;
    float lens_radius = 0.f;
    float focus_distance = 1.f;
  };
  View make_view(const CameraParams& params) const;
  View view_at(float time) const;  // of a moving camera
  Ray ray_from(const View& view, Vec2 film, Vec2 lens, float time) const;
  // generate_ray of a moving camera: its view at `time`.
  Ray moving_ray(Vec2 film, Vec2 lens, float time) const;

  View view_;
  float width_ = 1.f, height_ = 1.f;
  float frame_time_ = 0.f;
  // The camera at the shutter's opening and closing, focus distances resolved.
  std::optional<std::array<CameraParams, 2>> motion_;
};

}  // namespace inkray
