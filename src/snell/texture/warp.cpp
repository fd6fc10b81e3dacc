#include "snell/texture/warp.hpp"

#include "snell/texture/povray_noise.hpp"

namespace snell::texture {

Vec3 vector_turbulence(const Vec3& p, int octaves, double omega, double lambda) {
  return povray_vector_turbulence(p, octaves, lambda, omega);
}

Vec3 TurbulenceWarp::warp(const Vec3& p) const {
  const Vec3 t = vector_turbulence(p, params_.octaves, params_.omega, params_.lambda);
  return p + Vec3{t.x * params_.amount.x, t.y * params_.amount.y, t.z * params_.amount.z};
}

}  // namespace snell::texture
