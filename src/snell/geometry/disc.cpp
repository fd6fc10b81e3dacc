#include "snell/geometry/disc.hpp"

#include <cmath>
#include <stdexcept>

namespace snell::geometry {

Disc::Disc(const Vec3& center, const Vec3& normal, double radius, double hole_radius)
    : center_(center), radius_(radius), hole_radius_(hole_radius) {
  if (!is_finite(center) || !is_finite(normal) || !std::isfinite(radius) || !std::isfinite(hole_radius))
    throw std::invalid_argument("disc: centre, normal and radii must be finite");
  const double len = length(normal);
  if (len < 1e-10) throw std::invalid_argument("disc: degenerate normal");
  if (radius < 0 || hole_radius < 0) throw std::invalid_argument("disc: radii must not be negative");
  normal_ = normal / len;
  orthonormal_basis(normal_, u_, v_);
}

Bounds3 Disc::bounds() const {
  const Vec3 e{radius_ * std::sqrt(std::max(0.0, 1 - normal_.x * normal_.x)),
               radius_ * std::sqrt(std::max(0.0, 1 - normal_.y * normal_.y)),
               radius_ * std::sqrt(std::max(0.0, 1 - normal_.z * normal_.z))};
  return {center_ - e, center_ + e};
}

bool Disc::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  const double denom = dot(normal_, ray.direction);
  if (denom == 0) return false;
  const double t = dot(normal_, center_ - ray.origin) / denom;
  if (!(t > t_min && t < t_max)) return false;
  const Vec3 rel = ray.at(t) - center_;
  const double x = dot(rel, u_), y = dot(rel, v_);
  const double r2 = x * x + y * y;
  // POV-Ray (disc.cpp) keeps hole_radius^2 <= r^2 <= radius^2.
  if (r2 > radius_ * radius_ || r2 < hole_radius_ * hole_radius_) return false;
  hit = LocalHit{};
  hit.t = t;
  hit.normal = normal_;
  hit.uv = radius_ > 0 ? Vec2{0.5 + 0.5 * x / radius_, 0.5 + 0.5 * y / radius_} : Vec2{};
  return true;
}

void Disc::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  LocalHit hit;
  if (intersect(ray, t_min, t_max, hit)) hits.push_back(hit);
}

// POV-Ray (disc.cpp, Disc::Inside): the whole half-space below the disc's plane is inside, whatever the
// radius, so a disc in CSG acts like a plane.
bool Disc::inside(const Vec3& p) const {
  return dot(p - center_, normal_) < 0;
}

}  // namespace snell::geometry
