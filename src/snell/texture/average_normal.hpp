#pragma once
// POV-Ray's `average` normal (reference, "Average"): `normal { average normal_map { [w1 N1] [w2 N2] } }`
// bends the normal by the weighted mean of what each entry's normal would make of it.
#include <utility>
#include <vector>

#include "snell/texture/pattern_normal.hpp"

namespace snell::texture {

class AverageNormal final : public material::Normal {
 public:
  /// Throws std::invalid_argument for an empty map or weights that sum to zero.
  explicit AverageNormal(std::vector<std::pair<double, NormalPtr>> entries);
  math::Vec3 perturb(const math::Vec3& normal, const material::PatternPoint& point) const override;

 private:
  std::vector<std::pair<double, NormalPtr>> entries_;
};

}  // namespace snell::texture
