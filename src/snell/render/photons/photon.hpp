#pragma once
// One stored photon: light that reached a surface after at least one specular bounce (a caustic photon).
#include "snell/math/color.hpp"
#include "snell/math/vec3.hpp"

namespace snell::render::photons {

struct Photon {
  math::Vec3 position;
  /// Unit direction back towards where the photon came from.
  math::Vec3 incoming;
  /// Power, scaled as POV-Ray does so that the gathered density reads as a light colour (photon_path.hpp).
  math::Color power;
};

}  // namespace snell::render::photons
