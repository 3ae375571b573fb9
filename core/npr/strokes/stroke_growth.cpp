// Stroke growth: a streamline of the (rotated) flow field on the surface,
// traced with fixed steps and re-projection.
#include "core/npr/strokes/stroke_growth.h"

#include "core/math/frame.h"
#include "core/math/hash.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

float unit_random(uint32_t seed, uint32_t stroke, uint32_t dimension) {
  return u32_to_unit_float(hash_combine(seed, stroke, dimension));
}

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

Vec3 tangent_part(const Vec3& v, const Normal3& n) { return v - n * glm::dot(n, v); }

Vec3 normalized_or_zero(const Vec3& v) {
  const float len = glm::length(v);
  return len > 0.f ? v / len : Vec3(0.f);
}

// v in the tangent plane, turned by `angle` about n.
Vec3 rotate_about(const Vec3& v, const Normal3& n, float angle) {
  return v * std::cos(angle) + glm::cross(n, v) * std::sin(angle);
}

// Direction of the next step at sp: the flow's tangent part turned by angle,
// blended towards the previous direction where the flow is nearly normal to the
// surface (poles, a box's top under a vertical flow) or would turn the stroke
// back on itself (past a pole); a stroke never folds back.
// sign is -1 for the half that grows against the flow.
Vec3 step_direction(const SurfacePoint& sp, const Vec3& flow, float sign, float angle, const Vec3& previous) {
  const Vec3 flow_t = sign * tangent_part(flow, sp.n);
  const float strength = glm::length(flow_t);  // sine of the flow's angle to the normal
  const Vec3 target = strength > 1e-6f ? rotate_about(flow_t / strength, sp.n, angle) : Vec3(0.f);
  const Vec3 carried = normalized_or_zero(tangent_part(previous, sp.n));
  if (carried == Vec3(0.f)) {
    if (strength > 1e-3f) return target;
    return sign * rotate_about(Frame::from_z(sp.n).x, sp.n, angle);
  }
  const float trust = smoothstep(0.05f, 0.35f, strength) * smoothstep(0.f, 0.5f, glm::dot(target, carried));
  const Vec3 d = normalized_or_zero(carried + trust * (target - carried));
  return d == Vec3(0.f) ? carried : d;
}

// Walks up to `steps` steps from start, writing the stations after start to
// out in order; returns how many it wrote before a step left the surface.
int walk(const StrokeSurface& surface, const SurfacePoint& start, const Vec3& flow, float sign,
         const StrokeShape& shape, float step, int steps, SurfacePoint* out) {
  SurfacePoint sp = start;
  Vec3 previous(0.f);
  for (int k = 0; k < steps; ++k) {
    // The rotation varies along the stroke by `bend`; s is the position in [-0.5, 0.5].
    const float s = sign * (float(k) + 0.5f) * step / std::max(shape.length, 1e-30f);
    const Vec3 d = step_direction(sp, flow, sign, shape.angle + shape.bend * s, previous);
    const Point3 target = sp.p + step * d;
    const SurfacePoint next = surface.project(target, glm::length(target - sp.p));
    if (!step_lands(sp, next, step)) return k;
    previous = next.p - sp.p;
    if (previous == Vec3(0.f)) previous = d;  // a step that projected back onto itself
    sp = next;
    out[k] = sp;
  }
  return steps;
}

}  // namespace

StrokeShape draw_stroke_shape(const StrokeEmitterDesc& e, uint32_t seed, uint32_t stroke) {
  StrokeShape shape;
  const float w_lo = std::min(e.width_min, e.width_max), w_hi = std::max(e.width_min, e.width_max);
  const float l_lo = std::min(e.length_min, e.length_max), l_hi = std::max(e.length_min, e.length_max);
  shape.length = l_lo + (l_hi - l_lo) * unit_random(seed, stroke, 0);
  shape.width = w_lo + (w_hi - w_lo) * unit_random(seed, stroke, 1);
  const float jitter = glm::radians(e.rotation_jitter);
  shape.angle = jitter * (2.f * unit_random(seed, stroke, 2) - 1.f);
  // A painter's stroke curves a little: up to half the rotation jitter end to end.
  shape.bend = 0.5f * jitter * (2.f * unit_random(seed, stroke, 3) - 1.f);
  return shape;
}

bool step_lands(const SurfacePoint& from, const SurfacePoint& to, float step) {
  if (to.boundary) return false;
  const float moved = glm::length(to.p - from.p);
  // Further than the step: the closest point is on another part of the surface
  // (a fold of a thin part); so is one whose normal turned by over 100 degrees.
  return moved <= 1.5f * step && glm::dot(from.n, to.n) > kLandingCos;
}

void grow_stroke(const StrokeSurface& surface, const SurfacePoint& root, const Vec3& flow,
                 const StrokeShape& shape, int segments, StrokeSpine* spine) {
  segments = std::max(segments, 1);
  const int back = segments / 2, front = segments - back;
  const float step = shape.length / float(segments);
  std::vector<SurfacePoint>& st = spine->stations;
  st.resize(size_t(segments) + 1);
  // The tail half walks against the flow; its stations come out root-first.
  const int tail = walk(surface, root, flow, -1.f, shape, step, back, st.data());
  std::reverse(st.begin(), st.begin() + tail);
  st[size_t(tail)] = root;
  const int tip = walk(surface, root, flow, 1.f, shape, step, front, st.data() + tail + 1);
  st.resize(size_t(tail + 1 + tip));
  spine->v.resize(st.size());
  for (size_t j = 0; j < st.size(); ++j) spine->v[j] = float(back - tail + int(j)) / float(segments);
  spine->cut_tail = tail < back;
  spine->cut_tip = tip < front;
}

}  // namespace inkray
