#include "snell/texture/slope_pattern.hpp"

#include <algorithm>
#include <cmath>

namespace snell::texture {

namespace {
constexpr double kPi = 3.14159265358979323846;

double stretch(double v, double low, double high) {
  return high - low != 0 ? (v - low) / (high - low) : v;
}

/// Into [0,1) as POV-Ray wraps the value, keeping an exact 1 just below it rather than at the bottom of
/// the map (pattern.cpp, slope_pattern).
double wrapped(double v) {
  if (v >= 1 && v - 1 < 1e-10) return 1 - 1e-10;
  return v - std::floor(v);
}
}  // namespace

SlopePattern::SlopePattern(const SlopeParams& params) : params_(params) {
  const double slope_length = length(params_.direction);
  unit_direction_ = slope_length > 0 ? params_.direction * (1 / slope_length) : Vec3{0, 1, 0};
  if (params_.altitude) {
    const double altitude_length = length(*params_.altitude);
    // POV-Ray (parstxtr.cpp) weighs slope and altitude by their vectors' lengths, then uses the altitude
    // direction as a unit vector.
    unit_altitude_ = altitude_length > 0 ? *params_.altitude * (1 / altitude_length) : Vec3{0, 0, 0};
    const double sum = slope_length + altitude_length;
    if (sum > 0) {
      slope_weight_ = slope_length / sum;
      altitude_weight_ = altitude_length / sum;
    }
  }
}

double SlopePattern::value_at(const Vec3& p, const Vec3& world_normal, const Vec3& ray_direction) const {
  // POV-Ray measures the slope of the normal turned to face the ray (trace.cpp sets PNormal after that
  // flip), so a surface seen from below slopes the other way.
  const Vec3 facing = dot(world_normal, ray_direction) > 0 ? -world_normal : world_normal;
  const double cosine = std::clamp(dot(facing, unit_direction_), -1.0, 1.0);
  double slope = stretch((std::asin(cosine) / kPi * 2 + 1) * 0.5, params_.low, params_.high);
  if (!params_.altitude) return wrapped(slope);
  const double height = stretch(dot(p, unit_altitude_), params_.altitude_low, params_.altitude_high);
  // The blend wraps too: a low point on a flat face can fall below 0 and come back near 1.
  return wrapped(slope_weight_ * slope + altitude_weight_ * height);
}

}  // namespace snell::texture
