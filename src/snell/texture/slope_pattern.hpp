#pragma once
// `slope { <direction> [, low, high] [altitude <direction> [, low, high]] }` (POV-Ray 3.7 reference,
// "slope"; as POV-Ray's pattern.cpp computes it): how steeply the surface faces `direction`, optionally
// mixed with the height of the point along `altitude`. Terrain textures use it for rock on steep faces.
#include <optional>

#include "snell/texture/pattern.hpp"

namespace snell::texture {

struct SlopeParams {
  Vec3 direction{0, 1, 0};
  /// Values between low and high are stretched to [0,1] (both 0: no stretch).
  double low = 0, high = 0;
  std::optional<Vec3> altitude;
  double altitude_low = 0, altitude_high = 0;
};

class SlopePattern final : public ValuePattern {
 public:
  explicit SlopePattern(const SlopeParams& params);
  /// Without a normal there is no slope: 0.
  double value(const Vec3&) const override { return 0; }
  /// asin(n . d) mapped from [-pi/2, pi/2] to [0, 1] (1 facing `direction`, 0.5 sideways), then blended
  /// with the height along the unit altitude direction by the two vectors' lengths, wrapped into [0, 1).
  double value_at(const Vec3& p, const Vec3& world_normal, const Vec3& ray_direction) const override;

 private:
  SlopeParams params_;
  Vec3 unit_direction_, unit_altitude_;
  double slope_weight_ = 1, altitude_weight_ = 0;
};

}  // namespace snell::texture
