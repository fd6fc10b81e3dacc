#include "snell/texture/slope_pattern.hpp"

#include <algorithm>
#include <cmath>

namespace snell::texture {

namespace {
constexpr double kPi = 3.14159265358979323846;

double stretch(double v, double low, double high) {
  return high - low != 0 ? (v - low) / (high - low) : v;
}
}  // namespace

SlopePattern::SlopePattern(const SlopeParams& params) : params_(params) {
  const double slope_length = length(params_.direction);
  unit_direction_ = slope_length > 0 ? params_.direction * (1 / slope_length) : Vec3{0, 1, 0};
  if (params_.altitude) {
    const double altitude_length = length(*params_.altitude);
    const double sum = slope_length + altitude_length;
    if (sum > 0) {
      slope_weight_ = slope_length / sum;
      altitude_weight_ = altitude_length / sum;
    }
  }
}

double SlopePattern::value_at(const Vec3& p, const Vec3& world_normal, const Vec3&) const {
  const double cosine = std::clamp(dot(world_normal, unit_direction_), -1.0, 1.0);
  double slope = stretch((std::asin(cosine) / kPi * 2 + 1) * 0.5, params_.low, params_.high);
  if (!params_.altitude) {
    // Wrapped into [0,1), keeping an exact 1 just below it rather than at the bottom of the map.
    if (slope >= 1 && slope - 1 < 1e-10) return 1 - 1e-10;
    return slope - std::floor(slope);
  }
  const double height = stretch(dot(p, *params_.altitude), params_.altitude_low, params_.altitude_high);
  return slope_weight_ * slope + altitude_weight_ * height;
}

}  // namespace snell::texture
