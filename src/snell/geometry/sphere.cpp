#include "snell/geometry/sphere.hpp"

#include <cmath>

#include "snell/geometry/surface_uv.hpp"
#include "snell/math/constants.hpp"

namespace snell::geometry {

std::shared_ptr<const Shape> Sphere::placed(const math::Transform& t) const {
  const auto s = t.uniform_scale();
  if (!s) return nullptr;
  return std::make_shared<Sphere>(t.point(center_), radius_ * *s);
}

Bounds3 Sphere::bounds() const {
  return {center_ - Vec3(radius_), center_ + Vec3(radius_)};
}

bool Sphere::roots(const Ray& ray, double& t0, double& t1) const {
  // Numerically stable form (pbrt-v4 6.1.4): work from the offset to the centre and compute the
  // discriminant as r^2 - |f - (f.d^)d^|^2, which keeps precision for distant spheres.
  const Vec3 f = ray.origin - center_;
  const double a = dot(ray.direction, ray.direction);
  const double b = dot(f, ray.direction);
  const Vec3 perp = f - (b / a) * ray.direction;
  const double disc = a * (radius_ * radius_ - dot(perp, perp));
  if (disc < 0) return false;
  const double root = std::sqrt(disc);
  const double q = b < 0 ? -b + root : -b - root;  // -(b + sign(b) root)
  if (q == 0) {
    t0 = t1 = 0;
    return true;
  }
  t0 = q / a;
  t1 = (dot(f, f) - radius_ * radius_) / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

LocalHit Sphere::make_hit(const Ray& ray, double t) const {
  LocalHit hit;
  hit.t = t;
  hit.normal = (ray.at(t) - center_) / radius_;
  // Spherical uv as POV-Ray's uv_mapping for spheres: u around y, v from south to north pole; only when
  // something reads uv (surface_uv.hpp).
  if (!surface_uv_requested()) return hit;
  const Vec3& n = hit.normal;
  hit.uv = {0.5 + std::atan2(n.x, n.z) * 0.5 * math::kInvPi,
            0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) * math::kInvPi};
  return hit;
}

bool Sphere::nearest_root(const Ray& ray, double t_min, double t_max, double& t) const {
  double t0, t1;
  if (!roots(ray, t0, t1)) return false;
  t = t0 > t_min ? t0 : t1;
  return t > t_min && t < t_max;
}

bool Sphere::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  double t;
  if (!nearest_root(ray, t_min, t_max, t)) return false;
  hit = make_hit(ray, t);
  return true;
}

bool Sphere::crosses(const Ray& ray, double t_min, double t_max) const {
  double t;
  return nearest_root(ray, t_min, t_max, t);
}

void Sphere::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  double t0, t1;
  if (!roots(ray, t0, t1)) return;
  if (t0 > t_min && t0 < t_max) hits.push_back(make_hit(ray, t0));
  if (t1 > t_min && t1 < t_max && t1 != t0) hits.push_back(make_hit(ray, t1));
}

bool Sphere::span(const Ray& ray, double& t_entry, double& t_exit) const {
  // As two intersect calls would find them: the second crossing must lie strictly beyond the first.
  return roots(ray, t_entry, t_exit) && t_exit > t_entry;
}

bool Sphere::inside(const Vec3& p) const {
  return length_squared(p - center_) < radius_ * radius_;
}

}  // namespace snell::geometry
