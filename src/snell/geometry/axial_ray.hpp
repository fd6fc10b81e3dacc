#pragma once
// A ray prepared for shapes of revolution around the y axis (lathe, sor): unit direction and origin moved
// to the ray's closest approach to the shape's origin, so that polynomial coefficients stay of the shape's
// size however far the ray starts. A point of the ray is o + u dn with u = f + t |d|; its squared distance
// from the axis is a u^2 + b u + c.
#include <cmath>

#include "snell/math/ray.hpp"

namespace snell::geometry {

struct AxialRay {
  math::Vec3 o, dn;
  double f = 0, length = 0;
  double a = 0, b = 0, c = 0;

  /// False for a degenerate (zero or non-finite) direction.
  bool prepare(const math::Ray& ray) {
    length = math::length(ray.direction);
    if (!(length > 0) || !std::isfinite(length)) return false;
    dn = ray.direction / length;
    f = dot(ray.origin, dn);
    o = ray.origin - f * dn;
    a = dn.x * dn.x + dn.z * dn.z;
    b = 2 * (o.x * dn.x + o.z * dn.z);
    c = o.x * o.x + o.z * o.z;
    return true;
  }
  /// Whether the ray never comes within `radius` of the axis.
  bool misses_cylinder(double radius) const {
    return a > 0 && c - b * b / (4 * a) > radius * radius * (1 + 1e-9);
  }
  double t_of(double u) const { return (u - f) / length; }
};

}  // namespace snell::geometry
