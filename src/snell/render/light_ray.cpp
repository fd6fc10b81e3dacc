#include "snell/render/light_ray.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

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

/// Attenuation for the cone of a spotlight, given the cosine between the axis and the direction to the point
/// (POV-Ray 3.7 lightsource.cpp, Attenuate_Light): cos^tightness, times a smooth step from the falloff cone
/// to the radius cone. The step applies whenever cos(radius) > 0, so `radius 0` gives a beam that fades
/// all the way from its axis to the falloff angle.
/// cos(radius) and cos(max(falloff, radius)) of a spotlight, remembered per thread in a few slots keyed by
/// the light's address and checked against its angles, so scenes with several spotlights (media1 has three)
/// compute the two cosines once per light, not twice per lit point.
struct ConeCosines {
  const scene::Light* light = nullptr;
  double radius = 0, falloff = 0, cos_radius = 1, cos_falloff = 1;
};

const ConeCosines& cone_cosines(const scene::Light& light) {
  constexpr size_t kSlots = 8;
  thread_local ConeCosines slots[kSlots];
  const auto address = reinterpret_cast<std::uintptr_t>(&light);
  ConeCosines& slot = slots[(address / alignof(scene::Light)) % kSlots];
  if (slot.light != &light || slot.radius != light.radius || slot.falloff != light.falloff) {
    slot.light = &light;
    slot.radius = light.radius;
    slot.falloff = light.falloff;
    slot.cos_radius = std::cos(math::radians(light.radius));
    slot.cos_falloff = std::cos(math::radians(std::max(light.falloff, light.radius)));
  }
  return slot;
}

/// Attenuation for the cone of a spotlight, given the cosine between the axis and the direction to the point
/// (POV-Ray 3.7 lightsource.cpp, Attenuate_Light): cos^tightness, times a smooth step from the falloff cone
/// to the radius cone. The step applies whenever cos(radius) > 0, so `radius 0` gives a beam that fades
/// all the way from its axis to the falloff angle.
double spot_attenuation(const scene::Light& light, double cos_theta) {
  if (cos_theta <= 0) return 0;
  double a = light.tightness == 0   ? 1.0
             : light.tightness == 1 ? cos_theta
                                    : std::pow(cos_theta, light.tightness);
  const ConeCosines& cone = cone_cosines(light);
  if (cone.cos_radius > 0 && cos_theta < cone.cos_radius)
    a *= cone_spline(cone.cos_falloff, cone.cos_radius, cos_theta);
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

LightRay light_direction(const scene::Light& light, const Vec3& point, const Vec3& offset) {
  LightRay r;
  const Vec3 centre = light.position + offset;
  if (light.kind == scene::Light::Kind::parallel || light.kind == scene::Light::Kind::cylinder) {
    // Parallel beams: every point sees the light along the axis; shadows reach back to the plane through
    // the light's centre perpendicular to the axis.
    const Vec3 back = centre - light.point_at;
    r.direction = length_squared(back) > 0 ? normalize(back) : Vec3(0, 1, 0);
    r.distance = dot(centre - point, r.direction);
  } else {
    const Vec3 to_light = centre - point;
    r.distance = length(to_light);
    r.direction = r.distance > 0 ? to_light / r.distance : Vec3(0, 1, 0);
  }
  return r;
}

double light_attenuation(const scene::Light& light, const Vec3& point, const LightRay& toward) {
  double attenuation = 1;
  if (light.kind == scene::Light::Kind::spotlight)
    attenuation = spot_attenuation(light, -dot(toward.direction, light_axis(light)));
  else if (light.kind == scene::Light::Kind::cylinder)
    attenuation = cylinder_attenuation(light, light_axis(light), point);
  if (attenuation > 0 && light.fade_power > 0 && std::fabs(light.fade_distance) > 1e-10)
    attenuation *= 2.0 / (1.0 + std::pow(std::fabs(toward.distance) / light.fade_distance, light.fade_power));
  return attenuation;
}

LightRay light_ray(const scene::Light& light, const Vec3& point) {
  LightRay r = light_direction(light, point);
  r.color = light.color * light_attenuation(light, point, r);
  return r;
}

}  // namespace snell::render
