#include "snell/render/sphere_emitters.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "snell/geometry/sphere.hpp"

namespace snell::render {

using math::Vec3;

namespace {

/// 1 - cos(theta_max) of the cone a sphere of radius r subtends at distance d > r, without the
/// cancellation of 1 - sqrt(1 - x) for small x = (r/d)^2.
double one_minus_cos_max(double radius, double distance) {
  const double x = (radius * radius) / (distance * distance);
  return x / (1 + std::sqrt(std::max(0.0, 1 - x)));
}

}  // namespace

math::Color finish_emission(const material::Finish& f, const math::Color& ambient_light) {
  const bool reflects_light = f.diffuse > 0 || f.specular > 0 || f.phong > 0;
  math::Color e = f.emission;
  if (!reflects_light && f.ambient_set) e += f.ambient * ambient_light;
  return e;
}

std::vector<SphereEmitter> find_sphere_emitters(const scene::Scene& scene) {
  std::vector<SphereEmitter> emitters;
  for (const auto& object : scene.objects) {
    const auto* sphere = dynamic_cast<const geometry::Sphere*>(object->shape.get());
    if (!sphere || object->motion || object->flags.inverse) continue;
    const Vec3 center = object->transform.point(sphere->center());
    const Vec3 ax = object->transform.vector({sphere->radius(), 0, 0});
    const Vec3 ay = object->transform.vector({0, sphere->radius(), 0});
    const Vec3 az = object->transform.vector({0, 0, sphere->radius()});
    const double r = length(ax);
    const double tolerance = 1e-9 * r;
    const bool similar = std::abs(length(ay) - r) <= tolerance && std::abs(length(az) - r) <= tolerance &&
                         std::abs(dot(ax, ay)) <= tolerance * r && std::abs(dot(ax, az)) <= tolerance * r &&
                         std::abs(dot(ay, az)) <= tolerance * r;
    if (!similar || !(r > 0) ||
        finish_emission(object->texture->finish_at(center), scene.settings.ambient_light).is_black())
      continue;
    emitters.push_back({object.get(), center, r});
  }
  return emitters;
}

double sphere_cone_pdf(const SphereEmitter& emitter, const Vec3& point) {
  const double d = length(emitter.center - point);
  if (d <= emitter.radius) return 0;
  return 1 / (2 * std::numbers::pi * one_minus_cos_max(emitter.radius, d));
}

std::optional<Vec3> sample_sphere_cone(const SphereEmitter& emitter, const Vec3& point, double u1,
                                       double u2) {
  const Vec3 to_center = emitter.center - point;
  const double d = length(to_center);
  if (d <= emitter.radius) return std::nullopt;
  const Vec3 axis = to_center / d;
  const double one_minus_cos = u1 * one_minus_cos_max(emitter.radius, d);
  const double cos_t = 1 - one_minus_cos;
  const double sin_t = std::sqrt(std::max(0.0, one_minus_cos * (2 - one_minus_cos)));
  const double phi = 2 * std::numbers::pi * u2;
  Vec3 t, b;
  math::orthonormal_basis(axis, t, b);
  return normalize(sin_t * std::cos(phi) * t + sin_t * std::sin(phi) * b + cos_t * axis);
}

}  // namespace snell::render
