#include "snell/texture/facets.hpp"

#include <cmath>
#include <limits>

#include "snell/texture/povray_noise.hpp"

namespace snell::texture {

Vec3 FacetsPattern::nearest_point(const Vec3& q) const {
  // POV-Ray's PickInCube rounds coordinates within EPSILON above an integer down (normal.cpp, facets).
  auto cell = [](double x) { return static_cast<int>(std::floor(x - 1e-10)); };
  const int cx = cell(q.x), cy = cell(q.y), cz = cell(q.z);
  const double m = params_.metric;
  double best = std::numeric_limits<double>::infinity();
  Vec3 nearest = q;
  // With one point per cube the nearest can be up to two cubes away along one axis, never along two:
  // the 5x5x5 block less the cubes two away in more than one axis (POV-Ray's 81 cubes).
  for (int dx = -2; dx <= 2; ++dx)
    for (int dy = -2; dy <= 2; ++dy)
      for (int dz = -2; dz <= 2; ++dz) {
        if ((std::abs(dx) == 2) + (std::abs(dy) == 2) + (std::abs(dz) == 2) > 1) continue;
        const Vec3 c = povray_point_in_cube(cx + dx, cy + dy, cz + dz);
        const Vec3 d = c - q;
        const double distance = m == 2   ? dot(d, d)
                                : m == 1 ? d.x + d.y + d.z  // POV-Ray's metric 1 sums signed offsets
                                         : std::pow(std::fabs(d.x), m) + std::pow(std::fabs(d.y), m) +
                                               std::pow(std::fabs(d.z), m);
        if (distance < best) {
          best = distance;
          nearest = c;
        }
      }
  return nearest;
}

Vec3 FacetsPattern::set_normal(const Vec3& p, const Vec3& n, double) const {
  const double scale = params_.size < 1e-6 ? 1e6 : 1 / params_.size;
  const Vec3 unit = normalize(n);
  if (params_.coords == 0) return nearest_point(unit * scale);
  // The noise vector of the nearest point, less its part along the normal, tilts the normal.
  const Vec3 noise = povray_dnoise(nearest_point(p * scale));
  const Vec3 tangent = noise - unit * dot(noise, unit);
  return unit + tangent * params_.coords;
}

}  // namespace snell::texture
