#pragma once
#include "snell/math/vec3.hpp"

namespace snell::math {

/// A ray o + t d. `d` need not be unit length: rays carried into an object's local space keep the world
/// parameter t, so hits from differently transformed objects compare directly. `time` is the shutter time
/// in [0,1] for motion blur.
struct Ray {
  Vec3 origin;
  Vec3 direction;
  double time = 0;

  constexpr Vec3 at(double t) const { return origin + t * direction; }
};

}  // namespace snell::math
