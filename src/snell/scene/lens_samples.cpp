#include "snell/scene/lens_samples.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::scene {

math::Vec2 lens_sample(int index, int count, double rotation, double jitter_u, double jitter_v) {
  // Vogel 1979: point k at radius sqrt((k + 1/2) / n) and angle k * golden angle splits a disc into n cells
  // of equal area. The jitter moves the point within its ring (radius) and its angular cell.
  const double n = std::max(count, 1);
  const double golden_angle = math::kPi * (3.0 - std::sqrt(5.0));
  const double r = 0.5 * std::sqrt(std::clamp((index + jitter_u) / n, 0.0, 1.0));
  const double a = index * golden_angle + rotation + (jitter_v - 0.5) * (golden_angle / n);
  return {r * std::cos(a), r * std::sin(a)};
}

}  // namespace snell::scene
