#pragma once
// A pattern point at p, the rest left at its defaults: what the pattern normal tests look up.
#include "snell/material/pigment.hpp"

namespace snell::texture::test {

inline material::PatternPoint at(const math::Vec3& p) {
  material::PatternPoint point;
  point.p = p;
  return point;
}

}  // namespace snell::texture::test
