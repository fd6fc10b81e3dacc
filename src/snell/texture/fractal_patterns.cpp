#include "snell/texture/fractal_patterns.hpp"

#include <algorithm>
#include <cmath>

namespace snell::texture {

namespace {

/// Iterates z -> z^2 + c from z0 and values the result by `s`.
double iterate(double zr, double zi, double cr, double ci, const FractalShading& s) {
  double closest = zr * zr + zi * zi;
  for (int i = 0; i < s.max_iterations; ++i) {
    const double next_i = 2 * zr * zi + ci;
    zr = zr * zr - zi * zi + cr;
    zi = next_i;
    const double d2 = zr * zr + zi * zi;
    closest = std::min(closest, d2);
    if (d2 > 4) {
      switch (s.exterior_type) {
        case 0:
          return s.exterior_factor;
        case 2:
          return zr * s.exterior_factor;
        case 3:
          return zi * s.exterior_factor;
        default:
          return static_cast<double>(i) / s.max_iterations * s.exterior_factor;
      }
    }
  }
  switch (s.interior_type) {
    case 1:
      return std::sqrt(closest) * s.interior_factor;
    case 2:
      return zr * s.interior_factor;
    case 3:
      return zi * s.interior_factor;
    default:
      return s.interior_factor;
  }
}

}  // namespace

double MandelPattern::value(const Vec3& p) const {
  return iterate(p.x, p.y, p.x, p.y, shading_);
}

double JuliaPattern::value(const Vec3& p) const {
  return iterate(p.x, p.y, c_real_, c_imaginary_, shading_);
}

}  // namespace snell::texture
