#pragma once
// POV-Ray `normal {}` (POV-Ray 3.7 reference, "Normal"): a pattern that bends the shading normal so a
// flat surface looks bumpy. The patterns themselves live in texture/ (texture/pattern_normal.hpp).
#include "snell/material/pigment.hpp"
#include "snell/math/vec3.hpp"

namespace snell::material {

class Normal {
 public:
  virtual ~Normal() = default;
  /// `normal` (unit, in the texture's space) bent by the pattern at `point`; unit length.
  virtual math::Vec3 perturb(const math::Vec3& normal, const PatternPoint& point) const = 0;
};

}  // namespace snell::material
