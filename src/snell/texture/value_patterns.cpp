#include "snell/texture/value_patterns.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/fraction.hpp"
#include "snell/texture/povray_noise.hpp"

namespace snell::texture {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// POV-Ray's density clip: a distance d in [0,1] becomes 1 - d; negative gives 1, beyond 1 gives 0.
double clipped_falloff(double d) {
  if (d < 0) return 1;
  if (d > 1) return 0;
  return 1 - d;
}

}  // namespace

double GradientPattern::value(const Vec3& p) const {
  const double v = dot(p, direction_);
  return v > 1 ? math::fraction(v) : v;
}

double OnionPattern::value(const Vec3& p) const {
  return math::fraction(length(p));
}

double SphericalPattern::value(const Vec3& p) const {
  return clipped_falloff(length(p));
}

double CylindricalPattern::value(const Vec3& p) const {
  return clipped_falloff(std::sqrt(p.x * p.x + p.z * p.z));
}

double PlanarPattern::value(const Vec3& p) const {
  return clipped_falloff(std::fabs(p.y));
}

double BoxedPattern::value(const Vec3& p) const {
  return clipped_falloff(std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
}

double RadialPattern::value(const Vec3& p) const {
  // Near the axis the angle is meaningless; POV-Ray returns a fixed value there.
  if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
  return 0.25 + (std::atan2(p.x, p.z) + kPi) / (2 * kPi);
}

double LeopardPattern::value(const Vec3& p) const {
  const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3;
  return s * s;
}

double BozoPattern::value(const Vec3& p) const {
  return povray_noise(p, noise_.get());
}

}  // namespace snell::texture
