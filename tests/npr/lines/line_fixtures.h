// Chains and images the line stroke tests draw: straight lines, circles, S-curves.
#pragma once

#include "core/image/rgb_image.h"
#include "core/world/chain.h"
#include "core/world/line_sets.h"

#include <cmath>
#include <string>
#include <vector>

namespace inkray::test {

inline ChainPoint chain_point(Vec2 p) {
  ChainPoint q;
  q.p = p;
  q.depth = 5.f;
  return q;
}

// From a to b, points a pixel apart (as a traced chain's are).
inline Chain straight_chain(Vec2 a, Vec2 b, LineType type = LineType::silhouette) {
  Chain c;
  c.type = type;
  const int steps = std::max(1, int(std::ceil(glm::length(b - a))));
  for (int k = 0; k <= steps; ++k) c.points.push_back(chain_point(glm::mix(a, b, float(k) / float(steps))));
  return c;
}

// A closed circle, points about a pixel apart, curvature 1 / radius.
inline Chain circle_chain(Vec2 centre, float radius) {
  Chain c;
  c.closed = true;
  const int steps = std::max(8, int(std::ceil(2.f * 3.14159265f * radius)));
  for (int k = 0; k < steps; ++k) {
    const float a = 2.f * 3.14159265f * float(k) / float(steps);
    ChainPoint q = chain_point(centre + radius * Vec2(std::cos(a), std::sin(a)));
    q.curvature = 1.f / radius;
    c.points.push_back(q);
  }
  return c;
}

// An S: two half circles of `radius` joined, from the top, points about a pixel apart.
inline Chain s_curve_chain(Vec2 top, float radius) {
  Chain c;
  const int steps = std::max(8, int(std::ceil(3.14159265f * radius)));
  for (int half = 0; half < 2; ++half) {
    const Vec2 centre = top + Vec2(0.f, radius * float(2 * half + 1));
    for (int k = half; k <= steps; ++k) {
      const float a = 3.14159265f * float(k) / float(steps);
      // The first half turns left round its centre, the second right.
      const Vec2 p = half == 0 ? centre + radius * Vec2(-std::sin(a), -std::cos(a))
                               : centre + radius * Vec2(std::sin(a), -std::cos(a));
      ChainPoint q = chain_point(p);
      q.curvature = (half == 0 ? 1.f : -1.f) / radius;
      c.points.push_back(q);
    }
  }
  return c;
}

inline LineSet line_set(const std::string& name, const LineStyle& style, uint32_t types = ~0u) {
  LineSet set;
  set.name = name;
  set.style = style;
  set.select.types = types;
  return set;
}

inline RgbImage filled_image(int width, int height, Color c) {
  return RgbImage{width, height, std::vector<Color>(size_t(width) * size_t(height), c)};
}

}  // namespace inkray::test
