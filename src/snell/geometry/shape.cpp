#include "snell/geometry/shape.hpp"

#include "snell/math/constants.hpp"

namespace snell::geometry {

bool Shape::span(const Ray& ray, double& t_entry, double& t_exit) const {
  LocalHit entry, exit;
  if (!intersect(ray, -math::kInfinity, math::kInfinity, entry)) return false;
  if (!intersect(ray, entry.t, math::kInfinity, exit)) return false;
  t_entry = entry.t, t_exit = exit.t;
  return true;
}

}  // namespace snell::geometry
