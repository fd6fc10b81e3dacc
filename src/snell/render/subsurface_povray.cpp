#include "snell/render/subsurface_povray.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "snell/scene/object.hpp"

namespace snell::render {

using math::Color;
using math::Vec3;

double povray_diffuse_fresnel_reflectance(double eta) {
  // POV-Ray 3.7 subsurface.h: a stable stand-in for Egan and Hilgeman's fit.
  if (eta < 1) return eta * eta - std::pow(eta, 2.25);
  const double k = 1 - 1 / eta;
  return (k + 3 * std::pow(k, 4.5)) / 4;
}

double povray_fresnel_transmittance(double phi, double eta) {
  // Unpolarised Fresnel reflectance in Cook and Torrance's 1982 form, g = sqrt(eta^2 + c^2 - 1).
  const double c = std::cos(phi);
  const double g = std::sqrt(std::max(0.0, eta * eta + c * c - 1));
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1) / (c * (g - c) + 1);
  return 1 - std::clamp(0.5 * a * a * (1 + b * b), 0.0, 1.0);
}

namespace {

/// Jensen et al. 2001 section 2.3: total diffuse reflectance for reduced albedo `albedo` and boundary
/// term `a`.
double total_reflectance(double albedo, double a) {
  const double root = std::sqrt(3 * (1 - albedo));
  return albedo / 2 * (1 + std::exp(-4.0 / 3.0 * a * root)) * std::exp(-root);
}

double boundary_term(double eta) {
  const double fdr = povray_diffuse_fresnel_reflectance(eta);
  return (1 + fdr) / (1 - fdr);
}

struct Channel {
  double sigma_s = 0, sigma_a = 0, sigma_t = 0, sigma_tr = 0, albedo = 0;
};

/// Jensen et al. 2001 eq. 5, per mm^2, for squared distance `r2` (mm^2) from the point of incidence.
double dipole_reflectance(const Channel& c, double a, double r2) {
  const double zr = 1 / c.sigma_t, zv = zr * (1 + 4 * a / 3);
  const double dr2 = zr * zr + r2, dv2 = zv * zv + r2;
  const double dr = std::sqrt(dr2), dv = std::sqrt(dv2);
  const double real = zr * (c.sigma_tr + 1 / dr) * std::exp(-c.sigma_tr * dr) / dr2;
  const double virt = zv * (c.sigma_tr + 1 / dv) * std::exp(-c.sigma_tr * dv) / dv2;
  return c.albedo / (4 * std::numbers::pi) * (real + virt);
}

/// Direction `index` of `count` spread uniformly over the sphere: jittered strata of an m x m grid in
/// (z, phi) (m = floor(sqrt(count)); the rest plain random). Stratifying keeps the estimate unbiased and
/// lowers its noise against independent directions, so the same `samples` count gives a smoother image.
Vec3 stratified_sphere(int index, int count, math::Pcg32& rng) {
  const int m = static_cast<int>(std::sqrt(static_cast<double>(count)));
  double u1 = rng.next_double();
  double u2 = rng.next_double();
  if (index < m * m) {
    u1 = (index / m + u1) / m;
    u2 = (index % m + u2) / m;
  }
  const double z = 1 - 2 * u1;
  const double s = std::sqrt(std::max(0.0, 1 - z * z));
  const double phi = 2 * std::numbers::pi * u2;
  return {s * std::cos(phi), s * std::sin(phi), z};
}

double channel_of(const Color& c, int i) {
  return i == 0 ? c.r : i == 1 ? c.g : c.b;
}
double& channel_of(Color& c, int i) {
  return i == 0 ? c.r : i == 1 ? c.g : c.b;
}

const scene::Object* solid_of(const scene::SurfaceHit& hit) {
  return hit.solid ? hit.solid : hit.object;
}

constexpr double kNear = 1e-6;  // skips the surface a probe starts on

class Estimator {
 public:
  Estimator(const PovraySubsurfaceQuery& q, const accel::Accelerator& accel, math::Pcg32& rng,
            const LightsAt& lights)
      : q_(q), accel_(accel), rng_(rng), lights_(lights), a_(boundary_term(q.ior)) {
    for (int i = 0; i < 3; ++i) {
      Channel& c = channels_[i];
      c.albedo = std::max(povray_reduced_albedo(channel_of(q.reflectance, i), q.ior), 1e-6);
      c.sigma_s = 1 / std::max(std::fabs(channel_of(q.translucency, i)), 1e-9);
      c.sigma_t = c.sigma_s / c.albedo;
      c.sigma_a = c.sigma_t - c.sigma_s;
      c.sigma_tr = std::sqrt(3 * c.sigma_a * c.sigma_t);
      mean_sigma_a_ += kGrey[i] * c.sigma_a;
      mean_sigma_s_ += kGrey[i] * c.sigma_s;
    }
    cos_out_ = std::clamp(dot(q.to_viewer, q.normal), -1.0, 1.0);
  }

  /// trace.cpp ComputeSubsurfaceScattering, diffuse part: probes from a base point below the surface.
  Color diffuse() {
    const Vec3 inward = -q_.normal;
    const double free_path = 1 / ((mean_sigma_a_ + mean_sigma_s_) * q_.mm_per_unit);
    Vec3 base = q_.point + free_path * inward;
    scene::SurfaceHit back;
    if (accel_.intersect(math::Ray{q_.point, inward, 0.0}, kNear, 2 * free_path, scene::RayKind::shadow,
                         back))
      base =
          q_.point + (solid_of(back) == q_.solid ? back.t / 2 : std::min(free_path, back.t - kNear)) * inward;
    const double ft_out = povray_fresnel_transmittance(std::acos(cos_out_), q_.ior);
    Color sum;
    int found = 0;
    for (int i = 0; i < q_.diffuse_samples; ++i) {
      const Vec3 v = stratified_sphere(i, q_.diffuse_samples, rng_);
      scene::SurfaceHit hit;
      if (!accel_.intersect(math::Ray{base, v, 0.0}, 0.0, std::numeric_limits<double>::infinity(),
                            scene::RayKind::shadow, hit))
        continue;
      ++found;  // every hit counts in the average, also one on another object (as POV-Ray does)
      if (solid_of(hit) != q_.solid) continue;
      const double cos_hit = std::max(0.01, std::fabs(dot(v, hit.normal)));
      const double area = 4 * std::numbers::pi * std::pow(hit.t * q_.mm_per_unit, 2) / cos_hit;
      const double r2 = length_squared(hit.point - q_.point) * q_.mm_per_unit * q_.mm_per_unit;
      incident_.clear();
      lights_(hit.point, hit.normal, incident_);
      for (const IncidentLight& light : incident_) {
        const double cos_in = std::fabs(dot(hit.normal, light.direction));
        if (cos_in < 1e-10 || light.color.is_black()) continue;
        const double f = povray_fresnel_transmittance(std::acos(cos_in), q_.ior) * ft_out;
        for (int c = 0; c < 3; ++c)
          channel_of(sum, c) +=
              channel_of(light.color, c) * cos_in * f * dipole_reflectance(channels_[c], a_, r2) * area;
      }
    }
    return found > 0 ? sum / static_cast<double>(found) : Color(0);
  }

  /// trace.cpp ComputeSingleScatteringContribution: one scattering event on the refracted eye ray.
  Color single() {
    const double inv_eta = 1 / q_.ior;
    const double cos_refracted2 = 1 - inv_eta * inv_eta * (1 - cos_out_ * cos_out_);
    if (cos_refracted2 < 0) return Color(0);
    const double cos_out_prime = std::sqrt(cos_refracted2);
    const Vec3 refracted =
        normalize(-inv_eta * q_.to_viewer + (inv_eta * cos_out_ - cos_out_prime) * q_.normal);
    scene::SurfaceHit exit;
    const double depth_mm =
        accel_.intersect(math::Ray{q_.point, refracted, 0.0}, kNear, std::numeric_limits<double>::infinity(),
                         scene::RayKind::shadow, exit)
            ? exit.t * q_.mm_per_unit
            : std::numeric_limits<double>::infinity();
    const double ft_out = povray_fresnel_transmittance(std::acos(cos_out_), q_.ior);
    Color sum;
    for (int i = 0; i < q_.single_samples; ++i)
      for (int c = 0; c < 3; ++c) {
        const Channel& ch = channels_[c];
        // Stratified exponential distances (one stratum per sample), unbiased like independent ones.
        const double u = (i + rng_.next_double()) / q_.single_samples;
        const double s_out = -std::log1p(-u) / ch.sigma_t;
        if (s_out >= depth_mm) continue;
        const Vec3 bend = q_.point + (s_out / q_.mm_per_unit) * refracted;
        channel_of(sum, c) += single_at(bend, s_out, c, cos_out_prime, ft_out);
      }
    return q_.single_samples > 0 ? sum / static_cast<double>(q_.single_samples) : Color(0);
  }

 private:
  /// Light reaching `bend` (s_out mm along the refracted eye ray) straight from the surface towards each
  /// light, in channel c (refraction of the incoming light ignored for the path, as POV-Ray does).
  double single_at(const Vec3& bend, double s_out, int c, double cos_out_prime, double ft_out) {
    const Channel& ch = channels_[c];
    directions_.clear();
    lights_(bend, q_.normal, directions_);
    double sum = 0;
    for (size_t k = 0; k < directions_.size(); ++k) {
      scene::SurfaceHit entry;
      if (!accel_.intersect(math::Ray{bend, directions_[k].direction, 0.0}, 0.0,
                            std::numeric_limits<double>::infinity(), scene::RayKind::shadow, entry) ||
          solid_of(entry) != q_.solid)
        continue;
      incident_.clear();
      lights_(entry.point, entry.normal, incident_);
      if (k >= incident_.size()) continue;
      const IncidentLight& light = incident_[k];
      const double cos_in = std::fabs(dot(entry.normal, light.direction));
      if (cos_in < 1e-10 || light.color.is_black()) continue;
      const double cos_in_prime2 = 1 - (1 - cos_in * cos_in) / (q_.ior * q_.ior);
      if (cos_in_prime2 <= 0) continue;
      const double cos_in_prime = std::sqrt(cos_in_prime2);
      if (cos_in_prime <= 1e-10) continue;
      const double s_in = length(bend - entry.point) * q_.mm_per_unit * cos_in / cos_in_prime;
      const double f = povray_fresnel_transmittance(std::acos(cos_in), q_.ior) * ft_out;
      const double sigma_tc = ch.sigma_t * (1 + std::fabs(cos_out_prime / cos_in_prime));
      // Isotropic phase function 1/4 (POV-Ray's lights carry the 1/pi).
      const double factor = ch.sigma_s * f * 0.25 / sigma_tc * std::exp(-(s_in + s_out) * ch.sigma_t);
      sum += channel_of(light.color, c) * cos_in * factor;
    }
    return sum;
  }

  static constexpr double kGrey[3] = {0.297, 0.589, 0.114};  // POV-Ray's Greyscale weights
  const PovraySubsurfaceQuery& q_;
  const accel::Accelerator& accel_;
  math::Pcg32& rng_;
  const LightsAt& lights_;
  double a_;
  Channel channels_[3];
  double mean_sigma_a_ = 0, mean_sigma_s_ = 0;
  double cos_out_ = 1;
  std::vector<IncidentLight> incident_, directions_;
};

}  // namespace

double povray_reduced_albedo(double rd, double ior) {
  rd = std::clamp(rd, 0.0, 1.0);
  const double a = boundary_term(ior);
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (total_reflectance(mid, a) < rd ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Color povray_subsurface_radiance(const PovraySubsurfaceQuery& query, const accel::Accelerator& accelerator,
                                 math::Pcg32& rng, const LightsAt& lights) {
  Estimator estimator(query, accelerator, rng, lights);
  return estimator.diffuse() + estimator.single();
}

}  // namespace snell::render
