#include "core/npr/lines/chain_shape.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace inkray {

void orient_chain(Chain& c) {
  auto& pts = c.points;
  if (pts.size() < 2) return;
  auto before = [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  if (!c.closed) {
    if (before(pts.back().p, pts.front().p)) {
      std::reverse(pts.begin(), pts.end());
      std::swap(c.ends_at_crossing[0], c.ends_at_crossing[1]);
    }
    return;
  }
  double area = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const Vec2 a = pts[i].p, b = pts[(i + 1) % pts.size()].p;
    area += double(a.x) * double(b.y) - double(b.x) * double(a.y);
  }
  // With y down, a loop clockwise on screen has a positive shoelace sum.
  if (area < 0.0) std::reverse(pts.begin(), pts.end());
  const auto top = std::min_element(pts.begin(), pts.end(), [](const ChainPoint& a, const ChainPoint& b) {
    return a.p.y < b.p.y || (a.p.y == b.p.y && a.p.x < b.p.x);
  });
  std::rotate(pts.begin(), top, pts.end());
}

void measure_curvature(Chain& c) {
  const size_t n = c.points.size();
  if (n < 3) return;
  for (size_t i = 0; i < n; ++i) {
    const bool end = i == 0 || i + 1 == n;
    if (end && !c.closed) continue;
    const Vec2 a = c.points[(i + n - 1) % n].p, b = c.points[i].p, d = c.points[(i + 1) % n].p;
    const Vec2 u = b - a, v = d - b;
    const float lu = glm::length(u), lv = glm::length(v);
    if (lu <= 0.f || lv <= 0.f) continue;
    const float turn = std::atan2(u.x * v.y - u.y * v.x, glm::dot(u, v));
    c.points[i].curvature = turn / (0.5f * (lu + lv));
  }
  if (!c.closed)
    c.points.front().curvature = c.points[1].curvature, c.points.back().curvature = c.points[n - 2].curvature;
}

}  // namespace inkray
