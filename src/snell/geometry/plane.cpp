#include "snell/geometry/plane.hpp"

#include <cmath>
#include <stdexcept>

namespace snell::geometry {

// POV-Ray 3.7 (parser.cpp, Parse_Plane) divides the normal by its length but keeps the distance as
// written, so `plane { 2*y, 1 }` is the plane y = 1 (not y = 0.5); lengths below EPSILON (1e-10) are an
// error there ("Degenerate plane normal").
Plane::Plane(const Vec3& normal, double distance) {
  if (!is_finite(normal) || !std::isfinite(distance))
    throw std::invalid_argument("plane: normal and distance must be finite");
  const double len = length(normal);
  if (len < 1e-10) throw std::invalid_argument("plane: degenerate plane normal");
  normal_ = normal / len;
  distance_ = distance;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    if (normal_[b] != 0 || normal_[c] != 0) continue;
    // n.p < d with n = +-e_a: p_a < d, or p_a > -d.
    if (normal_[a] > 0)
      bounds_.hi[a] = distance_;
    else
      bounds_.lo[a] = -distance_;
  }
}

bool Plane::crossing(const Ray& ray, double t_min, double t_max, double& t) const {
  const double denom = dot(normal_, ray.direction);
  if (denom == 0 || !std::isfinite(denom)) return false;
  t = (distance_ - dot(normal_, ray.origin)) / denom;
  return t > t_min && t < t_max;
}

bool Plane::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  double t;
  if (!crossing(ray, t_min, t_max, t)) return false;
  hit = LocalHit{};
  hit.t = t;
  hit.normal = normal_;
  const Vec3 p = ray.at(t);
  hit.uv = {p.x, p.z};
  return true;
}

bool Plane::crosses(const Ray& ray, double t_min, double t_max) const {
  double t;
  return crossing(ray, t_min, t_max, t);
}

void Plane::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  LocalHit hit;
  if (intersect(ray, t_min, t_max, hit)) hits.push_back(hit);
}

}  // namespace snell::geometry
