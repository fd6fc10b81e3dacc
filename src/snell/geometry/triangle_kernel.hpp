#pragma once
// Ray-triangle intersection shared by Triangle and Mesh: Moeller & Trumbore 1997, "Fast, Minimum Storage
// Ray/Triangle Intersection", in double precision. Edges count as inside on both sides, so a ray through a
// mesh edge hits one of the neighbours (no cracks). The direction need not be unit length.
#include <cmath>

#include "snell/math/ray.hpp"
#include "snell/math/vec3.hpp"

namespace snell::geometry {

struct TriangleHit {
  double t, b1, b2;  // b1, b2: barycentric weights of the second and third vertex
};

inline bool intersect_triangle(const math::Vec3& a, const math::Vec3& b, const math::Vec3& c,
                               const math::Ray& ray, double t_min, double t_max, TriangleHit& out) {
  const math::Vec3 e1 = b - a, e2 = c - a;
  const math::Vec3 p = cross(ray.direction, e2);
  const double det = dot(e1, p);
  if (det == 0 || !std::isfinite(det)) return false;
  const double inv = 1.0 / det;
  const math::Vec3 s = ray.origin - a;
  const double b1 = dot(s, p) * inv;
  if (b1 < 0 || b1 > 1) return false;
  const math::Vec3 q = cross(s, e1);
  const double b2 = dot(ray.direction, q) * inv;
  if (b2 < 0 || b1 + b2 > 1) return false;
  const double t = dot(e2, q) * inv;
  if (!(t > t_min && t < t_max)) return false;
  out = {t, b1, b2};
  return true;
}

}  // namespace snell::geometry
