#include "snell/render/light_ray.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::render {

using math::Vec3;

double cone_spline(double low, double high, double x) {
  if (x < low) return 0;
  if (x >= high) return 1;
  const double t = (x - low) / (high - low);
  return t * t * (3 - 2 * t);
}

namespace {

/// Unit axis of a spot/cylinder/parallel light: from its position towards point_at.
Vec3 light_axis(const scene::Light& light) {
  const Vec3 axis = light.point_at - light.position;
  return length_squared(axis) > 0 ? normalize(axis) : Vec3(0, -1, 0);
}

/// Attenuation for the cone of a spotlight, given the cosine between the axis and the direction to the point.
/// The radius/falloff angles are compared as cosines; tightness sharpens the beam as cos^tightness.
double spot_attenuation(const scene::Light& light, double cos_theta) {
  if (cos_theta <= 0) return 0;
  double a = light.tightness > 0 ? std::pow(cos_theta, light.tightness) : 1.0;
  const double cos_radius = std::cos(math::radians(light.radius));
  const double cos_falloff = std::cos(math::radians(std::max(light.falloff, light.radius)));
  if (light.radius > 0) a *= cone_spline(cos_falloff, cos_radius, cos_theta);
  return a;
}

/// A cylinder light is a spotlight whose cone is a tube: radius/falloff are distances from the axis.
double cylinder_attenuation(const scene::Light& light, const Vec3& axis, const Vec3& point) {
  const Vec3 v = point - light.position;
  const double along = dot(v, axis);
  if (along <= 0) return 0;
  const double off_axis = length(v - along * axis);
  const double falloff = std::max(light.falloff, light.radius);
  if (off_axis >= falloff || falloff <= 0) return 0;
  const double d = 1.0 - off_axis / falloff;
  double a = light.tightness > 0 ? std::pow(d, light.tightness) : 1.0;
  if (light.radius > 0 && off_axis > light.radius) a *= cone_spline(0.0, 1.0 - light.radius / falloff, d);
  return a;
}

}  // namespace

LightRay light_ray(const scene::Light& light, const Vec3& point) {
  LightRay r;
  double attenuation = 1;
  switch (light.kind) {
    case scene::Light::Kind::parallel:
    case scene::Light::Kind::cylinder: {
      // Parallel beams: every point sees the light along the axis; shadows reach back to the plane through
      // the light's position perpendicular to the axis.
      const Vec3 axis = light_axis(light);
      r.direction = -axis;
      r.distance = dot(light.position - point, r.direction);
      if (light.kind == scene::Light::Kind::cylinder) attenuation = cylinder_attenuation(light, axis, point);
      break;
    }
    case scene::Light::Kind::point:
    case scene::Light::Kind::spotlight: {
      const Vec3 to_light = light.position - point;
      r.distance = length(to_light);
      r.direction = r.distance > 0 ? to_light / r.distance : Vec3(0, 1, 0);
      if (light.kind == scene::Light::Kind::spotlight)
        attenuation = spot_attenuation(light, -dot(r.direction, light_axis(light)));
      break;
    }
  }
  if (light.fade_power > 0 && std::fabs(light.fade_distance) > 1e-10)
    attenuation *= 2.0 / (1.0 + std::pow(std::fabs(r.distance) / light.fade_distance, light.fade_power));
  r.color = light.color * attenuation;
  return r;
}

}  // namespace snell::render
