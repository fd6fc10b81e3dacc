#include "snell/texture/spiral_patterns.hpp"

#include <cmath>

namespace snell::texture {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// 0 -> 1 -> 0 over each unit interval.
double triangle(double x) {
  const double f = x - std::floor(x);
  return f < 0.5 ? 2 * f : 2 * (1 - f);
}

/// z + r + arms * angle / 2 pi, the angle in [0, 2 pi) measured in the x-y plane from -y (POV-Ray's).
double helix(const Vec3& p, double arms) {
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  double angle = 0;
  if (r > 0) angle = p.x < 0 ? 1.5 * kPi - std::asin(p.y / r) : 0.5 * kPi + std::asin(p.y / r);
  return p.z + r + arms * angle / (2 * kPi);
}

}  // namespace

double Spiral1Pattern::value(const Vec3& p) const {
  return helix(p, arms_);
}

double Spiral2Pattern::value(const Vec3& p) const {
  return triangle(std::sqrt(p.x * p.x + p.y * p.y)) + triangle(helix(p, arms_));
}

double QuiltedPattern::value(const Vec3& p) const {
  const Vec3 offset{p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5, p.z - std::floor(p.z) - 0.5};
  const double t = length(offset);
  const double s = 1 - t;
  // Cubic Bezier with end points 0 and 1 and the two control values.
  const double curve = t * t * t + 3 * t * s * s * control0_ + 3 * t * t * s * control1_;
  const Vec3 q = offset * curve;
  return (std::fabs(q.x) + std::fabs(q.y) + std::fabs(q.z)) / 3;
}

}  // namespace snell::texture
