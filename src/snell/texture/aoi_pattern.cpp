#include "snell/texture/aoi_pattern.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::texture {

double AoiPattern::value_at(const Vec3&, const Vec3& world_normal, const Vec3& ray_direction) const {
  const double lengths = length(world_normal) * length(ray_direction);
  if (!(lengths > 0)) return 0;
  // The normal facing the ray makes the cosine negative (POV-Ray trace.cpp flips the raw normal so).
  const double cosine = -std::fabs(dot(world_normal, ray_direction)) / lengths;
  return std::acos(std::clamp(cosine, -1.0, 1.0)) / math::kPi;
}

}  // namespace snell::texture
