#include "snell/geometry/plane.hpp"

namespace snell::geometry {

Plane::Plane(const Vec3& normal, double distance) {
  const double len = length(normal);
  normal_ = len > 0 ? normal / len : Vec3(0, 1, 0);
  distance_ = distance;  // TODO(geometry): check POV-Ray scales d when the normal is not unit
}

bool Plane::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  const double denom = dot(normal_, ray.direction);
  if (denom == 0) return false;
  const double t = (distance_ - dot(normal_, ray.origin)) / denom;
  if (!(t > t_min && t < t_max)) return false;
  hit = LocalHit{};
  hit.t = t;
  hit.normal = normal_;
  const Vec3 p = ray.at(t);
  hit.uv = {p.x, p.z};
  return true;
}

void Plane::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  LocalHit hit;
  if (intersect(ray, t_min, t_max, hit)) hits.push_back(hit);
}

}  // namespace snell::geometry
