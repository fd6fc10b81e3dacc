#pragma once
// POV-Ray's `pigment_pattern { pigment {...} }` (reference, "Pigment Pattern"): a pigment used as a value
// pattern through its grey value, 0.297 R + 0.589 G + 0.114 B (POV-Ray's greyscale weights, colour.h).
#include <memory>

#include "snell/material/pigment.hpp"
#include "snell/texture/pattern.hpp"

namespace snell::texture {

class PigmentPattern final : public ValuePattern {
 public:
  explicit PigmentPattern(std::shared_ptr<const material::Pigment> pigment) : pigment_(std::move(pigment)) {}
  double value(const Vec3& p) const override {
    material::PatternPoint point;
    point.p = p;
    const math::Color c = pigment_->at(point).rgb;
    return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
  }

 private:
  std::shared_ptr<const material::Pigment> pigment_;
};

}  // namespace snell::texture
