#pragma once
#include <memory>
#include <vector>

#include "snell/material/media.hpp"
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
  /// Media filling the solid; POV-Ray renders them only when the object is `hollow`.
  std::vector<Media> media;

  /// This interior with its media moved by `t` (itself when it has none).
  static std::shared_ptr<const Interior> transformed(const std::shared_ptr<const Interior>& interior,
                                                     const math::Transform& t);
};

}  // namespace snell::material
