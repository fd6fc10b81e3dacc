#pragma once
#include "snell/math/color.hpp"

namespace snell::material {

/// POV-Ray `interior {}`: what light meets inside a solid.
struct Interior {
  double ior = 1;
  double dispersion = 1;
  double caustics = 0;
  double fade_distance = 0;
  double fade_power = 0;
  math::Color fade_color{0};
};

}  // namespace snell::material
