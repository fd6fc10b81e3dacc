#include "snell/geometry/triangle.hpp"

#include <stdexcept>

namespace snell::geometry {

Triangle::Triangle(const Vec3& a, const Vec3& b, const Vec3& c) : v_{a, b, c} {
  if (!is_finite(a) || !is_finite(b) || !is_finite(c))
    throw std::invalid_argument("triangle: vertices must be finite");
}

Triangle::Triangle(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb, const Vec3& c,
                   const Vec3& nc)
    : Triangle(a, b, c) {
  if (!is_finite(na) || !is_finite(nb) || !is_finite(nc))
    throw std::invalid_argument("smooth_triangle: normals must be finite");
  // A zero vertex normal cannot be interpolated; POV-Ray then falls back to the flat triangle.
  smooth_ = length_squared(na) > 0 && length_squared(nb) > 0 && length_squared(nc) > 0;
  if (smooth_) n_ = {normalize(na), normalize(nb), normalize(nc)};
}

Bounds3 Triangle::bounds() const {
  Bounds3 b(v_[0], v_[1]);
  b.unite(v_[2]);
  return b;
}

bool Triangle::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  TriangleHit th;
  if (!crossing(ray, t_min, t_max, th)) return false;
  hit = local_hit(th);
  return true;
}

LocalHit Triangle::local_hit(const TriangleHit& th) const {
  LocalHit hit = flat_hit(v_, th);
  if (smooth_) {
    hit.shading_normal = normalize((1 - th.b1 - th.b2) * n_[0] + th.b1 * n_[1] + th.b2 * n_[2]);
  }
  return hit;
}

LocalHit Triangle::flat_hit(const std::array<Vec3, 3>& v, const TriangleHit& th) {
  LocalHit hit;
  hit.t = th.t;
  hit.normal = normalize(cross(v[1] - v[0], v[2] - v[0]));
  hit.uv = {th.b1, th.b2};
  return hit;
}

void Triangle::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  LocalHit hit;
  if (intersect(ray, t_min, t_max, hit)) hits.push_back(hit);
}

// POV-Ray's Triangle::Inside is always false: a triangle has no interior.
bool Triangle::inside(const Vec3&) const {
  return false;
}

}  // namespace snell::geometry
