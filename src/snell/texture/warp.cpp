#include "snell/texture/warp.hpp"

#include "snell/texture/perlin_noise.hpp"

namespace snell::texture {

Vec3 vector_turbulence(const Vec3& p, int octaves, double omega, double lambda) {
  // Offsets far apart in lattice units decorrelate the components (any non-integer offsets do).
  const Vec3 offset_y{31.416, -47.853, 12.793};
  const Vec3 offset_z{-23.117, 19.532, 57.271};
  Vec3 sum{0, 0, 0};
  double amplitude = 1, frequency = 1;
  for (int i = 0; i < octaves; ++i) {
    const Vec3 q = p * frequency;
    sum = sum + Vec3{improved_perlin_noise(q), improved_perlin_noise(q + offset_y),
                     improved_perlin_noise(q + offset_z)} *
                    amplitude;
    amplitude *= omega;
    frequency *= lambda;
  }
  return sum;
}

Vec3 TurbulenceWarp::warp(const Vec3& p) const {
  const Vec3 t = vector_turbulence(p, params_.octaves, params_.omega, params_.lambda);
  return p + Vec3{t.x * params_.amount.x, t.y * params_.amount.y, t.z * params_.amount.z};
}

}  // namespace snell::texture
