#include "snell/texture/image_pattern.hpp"

namespace snell::texture {

double ImagePattern::value(const Vec3& p) const {
  material::PatternPoint point;
  point.p = p;
  const math::Color c = image_->at(point).rgb;
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

}  // namespace snell::texture
