#include "snell/scene/lens_samples.hpp"

#include <cmath>

#include "snell/math/constants.hpp"
#include "snell/math/fraction.hpp"

namespace snell::scene {

math::Vec2 r2_point(int index, double shift_u, double shift_v) {
  // R2: the plastic number g (g^3 = g + 1) gives steps 1/g and 1/g^2 in the unit square.
  constexpr double g = 1.32471795724474602596;
  return {math::fraction(shift_u + index / g), math::fraction(shift_v + index / (g * g))};
}

math::Vec2 lens_sample(int index, double shift_u, double shift_v) {
  const auto [u, v] = r2_point(index, shift_u, shift_v);
  // Equal areas of the square go to equal areas of the disc: radius sqrt(u).
  const double r = 0.5 * std::sqrt(u);
  const double a = math::kTwoPi * v;
  return {r * std::cos(a), r * std::sin(a)};
}

}  // namespace snell::scene
