#include "snell/render/path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "snell/math/constants.hpp"
#include "snell/render/interior_stack.hpp"
#include "snell/render/light_ray.hpp"
#include "snell/render/optics.hpp"
#include "snell/render/sphere_emitters.hpp"
#include "snell/render/whitted.hpp"

namespace snell::render {

using math::Color;
using math::Vec3;

namespace {

constexpr int kMaxBounces = 64;
constexpr int kRouletteAfter = 3;

/// A direction around unit `axis` with density (e+1)/(2 pi) cos^e (e = 1: cosine-weighted hemisphere).
Vec3 sample_lobe(const Vec3& axis, double exponent, math::Pcg32& rng) {
  const double u1 = rng.next_double();
  const double u2 = rng.next_double();
  const double cos_t = std::pow(1 - u1, 1 / (exponent + 1));
  const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
  const double phi = 2 * std::numbers::pi * u2;
  Vec3 t, b;
  math::orthonormal_basis(axis, t, b);
  return normalize(sin_t * std::cos(phi) * t + sin_t * std::sin(phi) * b + cos_t * axis);
}

/// Normalised Phong lobe value for a light direction (Lafortune and Willems 1994, "Using the modified
/// Phong reflectance model for physically based rendering"): (e+2)/(2 pi) cos^e, here times pi so that a
/// POV-Ray light of colour c gives c * cos for a Lambert albedo of 1.
double phong_lobe(const Vec3& mirror, const Vec3& wi, double exponent) {
  const double c = dot(mirror, wi);
  return c > 0 ? (exponent + 2) / 2 * std::pow(c, exponent) : 0;
}

/// How much of a surface shows itself rather than what lies behind it (POV-Ray 3.7's opacity).
double opacity_of(const material::Rgbft& pc) {
  return std::clamp(1.0 - pc.filter * pc.rgb.max() - pc.transmit, 0.0, 1.0);
}

double grey_max(const Color& c) {
  return std::max(0.0, c.max());
}

/// Density (e+1)/(2 pi) cos^e of `sample_lobe` around `axis` at direction `dir`.
double lobe_pdf(const Vec3& axis, const Vec3& dir, double exponent) {
  const double c = dot(axis, dir);
  return c > 0 ? (exponent + 1) / (2 * std::numbers::pi) * std::pow(c, exponent) : 0;
}

}  // namespace

PathIntegrator::PathIntegrator(const scene::Scene& scene, const accel::Accelerator& accelerator)
    : scene_(scene), accel_(accelerator), emitters_(find_sphere_emitters(scene)) {}

Color PathIntegrator::emitted(const material::Finish& f, const material::Rgbft& pc) const {
  return pc.rgb * finish_emission(f, scene_.settings.ambient_light) * opacity_of(pc);
}

double PathIntegrator::emitter_pdf(const scene::Object* object, const Vec3& from) const {
  for (const SphereEmitter& e : emitters_)
    if (e.object == object) return sphere_cone_pdf(e, from) / static_cast<double>(emitters_.size());
  return 0;
}

Color PathIntegrator::sample_emitters(const Vec3& point, const Vec3& n, const Vec3& wo, const Lobes& lobes,
                                      double time, TraceContext& context) const {
  if (emitters_.empty()) return {};
  // One emitter chosen uniformly, one direction in its cone.
  const double u0 = context.rng.next_double();
  const double u1 = context.rng.next_double();
  const double u2 = context.rng.next_double();
  const std::size_t count = emitters_.size();
  const SphereEmitter& e = emitters_[std::min(count - 1, static_cast<std::size_t>(u0 * count))];
  const auto dir = sample_sphere_cone(e, point, u1, u2);
  if (!dir) return {};
  const double cos_n = dot(n, *dir);
  if (cos_n <= 0) return {};
  const double pdf_light = sphere_cone_pdf(e, point) / static_cast<double>(count);
  scene::SurfaceHit hit;
  const math::Ray ray{offset_origin(point, n), *dir, time};
  if (!accel_.intersect(ray, 0.0, math::kInfinity, scene::RayKind::reflection, hit) || hit.object != e.object)
    return {};
  const Color le = emitted(hit.object->texture->finish_at(hit.point),
                           hit.object->texture->pigment_at(hit.point, hit.normal, hit.uv, ray.direction));
  // Each lobe is its own MIS pair (light sampling vs. that lobe's sampling, chosen with its probability).
  const Vec3 mirror = math::reflect(-wo, n);
  const double pdf_diffuse = lobes.p_diffuse * lobe_pdf(n, *dir, 1);
  const double pdf_glossy = lobes.p_glossy * lobe_pdf(mirror, *dir, lobes.exponent);
  const Color f_diffuse = lobes.albedo * (cos_n / std::numbers::pi);
  const Color f_glossy = lobes.glossy * ((lobes.exponent + 2) / (2 * std::numbers::pi) *
                                         std::pow(std::max(0.0, dot(mirror, *dir)), lobes.exponent) * cos_n);
  return le *
         (f_diffuse * power_heuristic(pdf_light, pdf_diffuse) +
          f_glossy * power_heuristic(pdf_light, pdf_glossy)) /
         pdf_light;
}

bool PathIntegrator::occluded(const Vec3& point, const Vec3& n, const Vec3& dir, double distance) const {
  const Vec3 origin = offset_origin(point, dot(n, dir) >= 0 ? n : -n);
  scene::SurfaceHit hit;
  return accel_.intersect({origin, dir, 0.0}, 0.0, distance - length(origin - point), scene::RayKind::shadow,
                          hit);
}

Color PathIntegrator::sample_lights(const Vec3& point, const Vec3& n, const Vec3& wo, const Color& albedo,
                                    const Color& glossy, double exponent, TraceContext& context) const {
  Color sum;
  const Vec3 mirror = math::reflect(-wo, n);
  for (const scene::Light& light : scene_.lights) {
    LightRay lr;
    if (light.area) {
      // One random point of the light's rectangle: an unbiased estimate of the grid's mean.
      const double u = context.rng.next_double() - 0.5;
      const double v = context.rng.next_double() - 0.5;
      const Vec3 offset = u * light.axis1 + v * light.axis2;
      lr = light_direction(light, point, offset);
      lr.color = light.color * light_attenuation(light, point, lr);
    } else {
      lr = light_ray(light, point);
    }
    const double cos_l = dot(n, lr.direction);
    if (cos_l <= 0 || lr.color.is_black()) continue;
    if (!light.shadowless && occluded(point, n, lr.direction, lr.distance)) continue;
    sum += lr.color * cos_l * (albedo + glossy * phong_lobe(mirror, lr.direction, exponent));
  }
  return sum;
}

Color PathIntegrator::trace_camera_ray(const math::Ray& camera_ray, TraceContext& context,
                                       double max_distance) const {
  Color radiance;
  Color throughput(1);
  math::Ray ray = camera_ray;
  InteriorStack inside;
  // The vertex the ray left from and the density with which its lobe chose the ray's direction (0 for
  // the camera and for mirror and refraction, which emitter sampling cannot reach).
  struct {
    Vec3 point;
    double lobe_pdf = 0;
  } previous;
  for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
    scene::SurfaceHit hit;
    // A mesh camera's max_distance limits the camera ray only.
    if (!accel_.intersect(ray, 0.0, bounce == 0 ? max_distance : math::kInfinity, scene::RayKind::camera,
                          hit)) {
      radiance += throughput * scene_.miss_color(ray.direction);
      break;
    }
    const material::Finish& f = hit.object->texture->finish_at(hit.point);
    const material::Rgbft pc = hit.object->texture->pigment_at(hit.point, hit.normal, hit.uv, ray.direction);
    const bool entering = dot(hit.normal, ray.direction) < 0;
    const Vec3 n = entering ? hit.normal : -hit.normal;
    const Vec3 wo = -ray.direction;
    const double opacity = opacity_of(pc);

    // Emission, weighted against the previous vertex's emitter sampling when it could have found it.
    if (const Color light = emitted(f, pc); !light.is_black()) {
      double weight = 1;
      if (previous.lobe_pdf > 0) {
        const double pdf_light = emitter_pdf(hit.object, previous.point);
        if (pdf_light > 0) weight = power_heuristic(previous.lobe_pdf, pdf_light);
      }
      radiance += throughput * light * weight;
    }

    // The finish's lobes and their weights.
    const Color albedo = pc.rgb * (f.diffuse * opacity);
    const double exponent = f.phong > 0 ? f.phong_size : 1 / std::max(f.roughness, 1e-4);
    const Color glossy = Color(f.phong > 0 ? f.phong : f.specular) * opacity;
    const Color mirror_colour = f.reflection_max * opacity;
    const Color transmit = pc.rgb * pc.filter + Color(pc.transmit);
    const double weights[4] = {grey_max(albedo), grey_max(glossy), grey_max(mirror_colour),
                               grey_max(transmit)};
    const double total = weights[0] + weights[1] + weights[2] + weights[3];
    if (total <= 0) break;

    const Lobes lobes{albedo, glossy, exponent, weights[0] / total, weights[1] / total};
    if (weights[0] + weights[1] > 0) {
      radiance += throughput * sample_lights(hit.point, n, wo, albedo, glossy, exponent, context);
      radiance += throughput * sample_emitters(hit.point, n, wo, lobes, ray.time, context);
    }

    // Choose one lobe in proportion to its weight; the throughput divides by that probability.
    double pick = context.rng.next_double() * total;
    int lobe = 0;
    while (lobe < 3 && pick >= weights[lobe]) pick -= weights[lobe++];
    const double p = weights[lobe] / total;
    Vec3 dir;
    bool through = false;
    if (lobe == 0) {
      dir = sample_lobe(n, 1, context.rng);
      throughput *= albedo / p;
      previous.lobe_pdf = lobes.p_diffuse * lobe_pdf(n, dir, 1);
      // Direct light was counted by next-event estimation; indirect light only from here on.
    } else if (lobe == 1) {
      dir = sample_lobe(math::reflect(ray.direction, n), exponent, context.rng);
      if (dot(dir, n) <= 0) break;
      // Lobe density (e+1)/(2pi) cos^e against the normalised lobe (e+2)/(2pi) cos^e times cos(n, dir).
      throughput *= glossy * ((exponent + 2) / (exponent + 1) * dot(dir, n) / p);
      previous.lobe_pdf = lobes.p_glossy * lobe_pdf(math::reflect(ray.direction, n), dir, exponent);
    } else if (lobe == 2) {
      dir = math::reflect(ray.direction, n);
      throughput *= mirror_colour / p;
      previous.lobe_pdf = 0;
    } else {
      const scene::Object* solid = hit.solid ? hit.solid : hit.object;
      const double ior = ior_of(solid);
      const double n1 = entering ? (inside.empty() ? 1.0 : ior_of(inside.back())) : ior;
      const double n2 = entering ? ior : 1.0;
      const double fr = std::clamp(fresnel_dielectric(dot(wo, n), n1, n2), 0.0, 1.0);
      const auto refracted = refract(ray.direction, n, n1 / n2);
      if (!refracted || context.rng.next_double() < fr) {
        dir = math::reflect(ray.direction, n);
      } else {
        dir = normalize(*refracted);
        through = true;
        if (entering)
          inside.push(solid);
        else
          inside.remove(solid);
      }
      throughput *= transmit / p;
      previous.lobe_pdf = 0;
    }
    previous.point = hit.point;
    // Emission of the next surface is counted as found, so a diffuse bounce must not see point lights
    // twice: point and area lights are not hittable here, so nothing is counted twice.
    if (bounce >= kRouletteAfter) {
      const double survive = std::min(0.95, grey_max(throughput));
      if (context.rng.next_double() >= survive) break;
      throughput = throughput / survive;
    }
    ray = {offset_origin(hit.point, through ? -n : n), dir, ray.time};
  }
  return radiance;
}

}  // namespace snell::render
