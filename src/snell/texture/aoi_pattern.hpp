#pragma once
// `aoi` (POV-Ray 3.7 reference, "Aoi"; POV-Ray's pattern.cpp AOIPattern): the angle between the ray and the
// surface normal turned towards it, as acos(cos)/pi. A surface seen head-on gives 1, one seen edge-on 0.5;
// the side the normal points to does not matter, as POV-Ray flips it to face the ray before evaluating.
#include "snell/texture/pattern.hpp"

namespace snell::texture {

class AoiPattern final : public ValuePattern {
 public:
  /// Without a ray there is no angle: 0, as POV-Ray returns where it has no intersection.
  double value(const Vec3&) const override { return 0; }
  double value_at(const Vec3& p, const Vec3& world_normal, const Vec3& ray_direction) const override;
};

}  // namespace snell::texture
