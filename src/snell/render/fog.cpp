#include "snell/render/fog.hpp"

#include <algorithm>
#include <cmath>

#include "snell/texture/povray_noise.hpp"

namespace snell::render {

using math::Color;
using math::Vec3;

namespace {

/// POV-Ray's stand-in for "no intersection" distance, so the sky is fogged completely but finitely.
constexpr double kSkyDepth = 1e10;
constexpr double kEpsilon = 1e-10;

/// Turbulence shortens the fogged width near the viewer: width (1 - k min(1, turbulence at p * turb_depth))
/// with k = exp(-width / distance), so distant fog stays smooth.
double turbulent_width(const scene::Fog& fog, const Vec3& p, double width) {
  const scene::FogTurbulence& t = *fog.turbulence;
  const Vec3 q{p.x * t.amount.x, p.y * t.amount.y, p.z * t.amount.z};
  const double k = std::exp(-width / fog.distance);
  const double turb = texture::povray_turbulence(q, t.octaves, t.lambda, t.omega);
  return width * (1.0 - k * std::min(1.0, turb * fog.turb_depth));
}

/// Mean ground fog density between heights (in units of fog_alt above fog_offset) `start` and `end`:
/// density is 1 below 0 and 1 / (1 + y^2) above, whose integral is atan(y).
double ground_fog_density(double start, double end) {
  if (start <= 0) return end <= 0 ? 1.0 : (std::atan(end) - start) / (end - start);
  if (end <= 0) return (std::atan(start) - end) / (start - end);
  const double delta = start - end;
  if (std::fabs(delta) > kEpsilon) return (std::atan(start) - std::atan(end)) / delta;
  return 1.0 / (start * start + 1.0);
}

}  // namespace

double fog_transmittance(const scene::Fog& fog, const math::Ray& ray, double depth) {
  if (std::fabs(fog.distance) <= kEpsilon) return 1.0;
  double width = std::min(depth, kSkyDepth);
  if (fog.type == scene::Fog::Type::ground) {
    const Vec3 p1 = ray.origin;
    const Vec3 p2 = p1 + ray.direction * width;
    const double alt = fog.altitude != 0 ? fog.altitude : kEpsilon;
    const double density =
        ground_fog_density((dot(p1, fog.up) - fog.offset) / alt, (dot(p2, fog.up) - fog.offset) / alt);
    if (fog.turbulence) width = turbulent_width(fog, (p1 + p2) * 0.5, width);
    return std::exp(-width * density / fog.distance);
  }
  if (fog.turbulence) width = turbulent_width(fog, ray.origin + ray.direction * (width / 2), width);
  return std::exp(-width / fog.distance);
}

FogEffect fogs_along(const std::vector<scene::Fog>& fogs, const math::Ray& ray, double depth) {
  FogEffect e;
  for (const scene::Fog& fog : fogs) {
    if (std::fabs(fog.distance) <= kEpsilon) continue;
    // Transmit sets a floor on what gets through; filter lets that much through tinted by the fog.
    const double t = std::max(fog_transmittance(fog, ray, depth), fog.color.transmit);
    e.through *= t * (Color(1 - fog.color.filter) + fog.color.filter * fog.color.rgb);
    e.added += (1 - t) * fog.color.rgb;
  }
  return e;
}

Color apply_fogs(const std::vector<scene::Fog>& fogs, const math::Ray& ray, double depth, const Color& seen) {
  const FogEffect e = fogs_along(fogs, ray, depth);
  return e.added + e.through * seen;
}

}  // namespace snell::render
