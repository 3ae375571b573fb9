// The filmic curve's inverse, solved in closed form.
#include "core/image/view_transform.h"

namespace inkray {

float filmic_curve_inverse(float y) {
  y = std::clamp(y, 0.f, 1.f);
  // y = u (2.51 u + 0.03) / (u (2.43 u + 0.59) + 0.14) with u = 0.6 x is the quadratic
  // a u^2 + b u + c = 0 below; a < 0 < c on [0, 1], so exactly one root is positive.
  // Each branch is the form of it without cancellation for the sign of b.
  const double a = 2.43 * y - 2.51, b = 0.59 * y - 0.03, c = 0.14 * y;
  const double root = std::sqrt(b * b - 4.0 * a * c);
  const double u = b <= 0.0 ? 2.0 * c / (root - b) : (-b - root) / (2.0 * a);
  return float(u / 0.6);
}

float filmic_white() {
  static const float white = filmic_curve_inverse(1.f);
  return white;
}

}  // namespace inkray
