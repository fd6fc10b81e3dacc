#pragma once
// Ken Perlin's improved noise (Perlin 2002, "Improving Noise", SIGGRAPH; reference Java implementation at
// mrl.nyu.edu/~perlin/noise/): gradient noise in about [-1, 1], zero at every integer lattice point.
#include "snell/math/vec3.hpp"

namespace snell::texture {

/// The quintic fade curve 6t^5 - 15t^4 + 10t^3 (continuous second derivative).
constexpr double perlin_fade(double t) {
  return t * t * t * (t * (t * 6 - 15) + 10);
}

double improved_perlin_noise(double x, double y, double z);
inline double improved_perlin_noise(const math::Vec3& p) {
  return improved_perlin_noise(p.x, p.y, p.z);
}

/// Improved noise moved to [0,1] (0.5 at the lattice points), the range of POV-Ray's Noise() that its
/// patterns expect.
inline double unit_noise(const math::Vec3& p) {
  const double n = 0.5 + 0.5 * improved_perlin_noise(p);
  return n < 0 ? 0 : (n > 1 ? 1 : n);
}

/// Sum of |noise| over `octaves`, each `lambda` times the frequency and `omega` times the amplitude of the
/// previous (POV-Ray's turbulence parameters; Perlin 1985's turbulence is lambda 2, omega 0.5).
double perlin_turbulence(const math::Vec3& p, int octaves, double lambda = 2.0, double omega = 0.5);

}  // namespace snell::texture
