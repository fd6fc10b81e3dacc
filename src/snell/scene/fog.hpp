#pragma once
// POV-Ray `fog {}` (POV-Ray 3.7 reference, "Fog"): constant fog (type 1) thins the light along a ray by
// exp(-d / distance); ground fog (type 2) is as dense below fog_offset and thins with height above it as
// 1 / (1 + ((h - fog_offset) / fog_alt)^2). Turbulence varies the depth a ray sees.
#include <optional>

#include "snell/material/rgbft.hpp"
#include "snell/math/vec3.hpp"

namespace snell::scene {

struct FogTurbulence {
  math::Vec3 amount{0, 0, 0};
  int octaves = 6;
  double omega = 0.5;
  double lambda = 2.0;
};

struct Fog {
  enum class Type { constant = 1, ground = 2 };
  Type type = Type::constant;
  double distance = 0;
  /// Filter and transmit let some of what lies behind through unfogged.
  material::Rgbft color;
  double offset = 0;
  double altitude = 0;
  /// Unit vector along which ground fog's height is measured.
  math::Vec3 up{0, 1, 0};
  std::optional<FogTurbulence> turbulence;
  double turb_depth = 0.5;
};

}  // namespace snell::scene
