#include "snell/render/subsurface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "snell/scene/object.hpp"

namespace snell::render {

using math::Color;
using math::Vec3;

material::Dipole finish_dipole(const material::Finish& finish, const Color& pigment, double eta) {
  if (finish.subsurface_material) return *finish.subsurface_material;
  return material::dipole_from_translucency(pigment * finish.diffuse, finish.subsurface_translucency, eta);
}

namespace {

/// Radii are drawn from an equal mixture of planar exponentials p(r) = s^2/(2 pi) e^{-s r} (per unit
/// area), one per channel for the far field (s = sigma_tr) and one per channel for the peak near the
/// entry point (s = sigma_t', the scale of z_r). The mixture keeps every channel's profile covered.
struct RadiusMixture {
  std::array<double, 6> rates{};

  explicit RadiusMixture(const material::Dipole& dipole) {
    for (int c = 0; c < 3; ++c) {
      const material::DipoleChannel ch = dipole.channel(c);
      const double t = std::max(ch.sigma_t_prime(), 1e-6);
      rates[2 * c] = std::clamp(ch.sigma_tr(), 1e-3 * t, t);
      rates[2 * c + 1] = t;
    }
  }

  /// Radius in mm for three uniform numbers (gamma distribution of shape 2: the radial marginal).
  double sample(double pick, double u1, double u2) const {
    const size_t k = std::min(rates.size() - 1, static_cast<size_t>(pick * rates.size()));
    return -(std::log1p(-u1) + std::log1p(-u2)) / rates[k];
  }

  /// Density per unit area (mm^-2) of the mixture at radius r (mm).
  double area_density(double r) const {
    double sum = 0;
    for (double s : rates) sum += s * s * std::exp(-s * r);
    return sum / (2 * std::numbers::pi * static_cast<double>(rates.size()));
  }
};

/// The first hit of `probe` within `length` on `solid`, passing through other objects (a glass around
/// the milk); bounded so that coincident surfaces cannot loop.
bool first_hit_on(const accel::Accelerator& accelerator, const math::Ray& probe, double length,
                  const scene::Object* solid, scene::SurfaceHit& hit) {
  double start = 0;
  for (int crossing = 0; crossing < 16; ++crossing) {
    if (!accelerator.intersect(probe, start, length, scene::RayKind::shadow, hit)) return false;
    if ((hit.solid ? hit.solid : hit.object) == solid) return true;
    start = hit.t + 1e-9 * (1 + hit.t);
  }
  return false;
}

}  // namespace

Color subsurface_radiance(const SubsurfaceQuery& q, const accel::Accelerator& accelerator, math::Pcg32& rng,
                          const IrradianceAt& irradiance) {
  const RadiusMixture mixture(q.dipole);
  Vec3 tangent, bitangent;
  math::orthonormal_basis(q.normal, tangent, bitangent);
  // The probe reaches a little deeper than one transport length below the tangent plane, so curved
  // surfaces near the point are found too.
  double deepest = 0;
  for (int c = 0; c < 3; ++c) deepest = std::max(deepest, q.dipole.channel(c).z_real());
  Color sum;
  for (int i = 0; i < q.samples; ++i) {
    const double pick = rng.next_double();
    const double u1 = rng.next_double();
    const double u2 = rng.next_double();
    const double phi = 2 * std::numbers::pi * rng.next_double();
    const double r_mm = mixture.sample(pick, u1, u2);
    const double r = r_mm / q.mm_per_unit;
    const double half = r + 4 * deepest / q.mm_per_unit + 1e-6;
    const Vec3 centre = q.point + r * (std::cos(phi) * tangent + std::sin(phi) * bitangent);
    const math::Ray probe{centre + half * q.normal, -q.normal, 0.0};
    scene::SurfaceHit hit;
    if (!first_hit_on(accelerator, probe, 2 * half, q.solid, hit)) continue;
    const double cos_n = std::fabs(dot(hit.normal, q.normal));
    if (cos_n < 1e-3) continue;
    const Color e = irradiance(hit.point, hit.normal);
    if (e.is_black()) continue;
    const double d_mm = length(hit.point - q.point) * q.mm_per_unit;
    // Area density of the found point: the planar density over the projection's cosine.
    sum += q.dipole.reflectance(d_mm) * e * (cos_n / mixture.area_density(r_mm));
  }
  return q.samples > 0 ? sum / static_cast<double>(q.samples) : Color(0);
}

}  // namespace snell::render
