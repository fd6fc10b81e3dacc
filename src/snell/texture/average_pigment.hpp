#pragma once
// POV-Ray's `average` pattern (reference, "Average"): `pigment { average pigment_map { [w1 P1] [w2 P2] ... }
// }` is the weighted mean of the map's pigments at every point, not a pattern lookup; weights need not sum
// to 1.
#include <vector>

#include "snell/texture/pattern_pigment.hpp"

namespace snell::texture {

class AveragePigment final : public material::Pigment {
 public:
  /// Throws std::invalid_argument for an empty map or weights that sum to zero.
  explicit AveragePigment(std::vector<PigmentMap::Entry> entries);
  material::Rgbft at(const material::PatternPoint& point) const override;

 private:
  std::vector<PigmentMap::Entry> entries_;
  double total_weight_ = 0;
};

}  // namespace snell::texture
