#include "snell/render/photons/photon_path.hpp"

#include <algorithm>
#include <cmath>

#include "snell/render/optics.hpp"
#include "snell/render/whitted.hpp"

namespace snell::render::photons {

using math::Color;
using math::Ray;
using math::Vec3;

namespace {

constexpr double kEpsilon = 1e-10;
/// A hit farther than this many times its point's magnitude is found again from close by (refine_far_hit),
/// from this many times that magnitude before it: well beyond the far hit's error, well within the scene.
constexpr double kFarHit = 1e3;
constexpr double kRefineBack = 1e-3;

/// Per-channel power, as POV-Ray raises a reflected colour to `reflection_exponent`.
Color channel_pow(const Color& c, double e) {
  return {std::pow(std::max(0.0, c.r), e), std::pow(std::max(0.0, c.g), e), std::pow(std::max(0.0, c.b), e)};
}

/// Fraction of the surface colour a metallic reflection takes on: POV-Ray's empirical curve of the angle of
/// incidence (trace.cpp, ComputeMetallic, [DB 9/94]), less tint towards grazing angles.
double metallic_grazing(double cos_i) {
  const double angle_fraction = std::acos(std::clamp(cos_i, -1.0, 1.0)) * (2.0 / 3.14159265358979323846);
  const double shifted = angle_fraction - 1.12;
  return std::clamp(0.014567225 / (shifted * shifted) - 0.011612903, 0.0, 1.0);
}

/// Interior fade over `distance` travelled inside (POV-Ray 3.7 reference, "Interior": fade_power 1000 and
/// above is exponential).
Color interior_fade(const material::Interior& interior, double distance) {
  if (std::fabs(interior.fade_distance) <= kEpsilon) return Color(1);
  const double depth = distance / interior.fade_distance;
  const Color& fc = interior.fade_color;
  if (interior.fade_power >= 1000)
    return {std::exp(-(1 - fc.r) * depth), std::exp(-(1 - fc.g) * depth), std::exp(-(1 - fc.b) * depth)};
  return fc + (Color(1) - fc) / (1 + std::pow(depth, interior.fade_power));
}

}  // namespace

Crossing cross_surface(const InteriorStack& inside, const scene::Object* object) {
  Crossing c{inside, 1.0};
  const double n_object = ior_of(object);
  if (inside.empty()) {
    c.next.push(object);
    c.eta = 1.0 / n_object;
  } else if (inside.back() == object) {
    c.next.remove(object);
    c.eta = n_object / (c.next.empty() ? 1.0 : ior_of(c.next.back()));
  } else if (!c.next.remove(object)) {
    c.eta = ior_of(inside.back()) / n_object;
    c.next.push(object);
  }
  return c;
}

Color finish_reflectivity(const material::Finish& f, const Color& pigment, double cos_i,
                          double relative_ior) {
  if (!f.reflects()) return Color(0);
  double towards_max;  // 0 gives reflection_min, 1 reflection_max
  if (f.reflection_fresnel) {
    towards_max = std::clamp(fresnel_dielectric(cos_i, 1.0, relative_ior), 0.0, 1.0);
  } else {
    const double grazing = std::max(0.0, 1 - cos_i);
    towards_max =
        std::fabs(f.reflection_falloff - 1) > kEpsilon ? std::pow(grazing, f.reflection_falloff) : grazing;
  }
  Color r = f.reflection_min + towards_max * (f.reflection_max - f.reflection_min);
  if (f.reflection_metallic > 0)
    r *= Color(1) + (f.reflection_metallic * (1 - metallic_grazing(cos_i))) * (pigment - Color(1));
  return r;
}

PhotonPath::PhotonPath(const accel::Accelerator& accel, const scene::Light& light,
                       const PhotonPathLimits& limits, double spread, const scene::PhotonTarget* target)
    : accel_(accel), light_(light), limits_(limits), spread_squared_(spread * spread), target_(target) {}

void PhotonPath::shoot(const Ray& ray, const Color& power, const InteriorStack& inside,
                       std::vector<Photon>& out) {
  follow(ray, Leg{power, 1.0, 1, 0.0, true}, inside, out);
}

void PhotonPath::store(const Vec3& point, const Vec3& incoming, const Leg& leg,
                       std::vector<Photon>& out) const {
  // The light's own fade over the whole path (POV-Ray applies it when storing, addSurfacePhoton).
  double scale = spread_squared_;
  if (light_.fade_power > 0 && std::fabs(light_.fade_distance) > kEpsilon)
    scale *= 2.0 / (1.0 + std::pow(leg.depth / light_.fade_distance, light_.fade_power));
  if (light_.kind != scene::Light::Kind::parallel && light_.kind != scene::Light::Kind::cylinder)
    scale *= leg.depth * leg.depth;
  out.push_back(Photon{point, incoming, leg.power * scale});
}

void PhotonPath::refine_far_hit(const Ray& ray, scene::SurfaceHit& hit) const {
  // A photon from a distant light (benchmark.pov's sun is 1.7e5 units off) meets a quadric through roots
  // whose discriminant cancels: the hit point's error grows as t^2 times the rounding unit, 1e-8 at
  // t = 3e4, far above the surface offset, so the point can lie inside the surface and the reflected photon
  // meets it again at once (such self-hits were half of that scene's stored photons). Found again from a
  // point just before it, the hit is as accurate as a near one.
  const double scale = 1 + max_component(abs(hit.point));
  if (!(hit.t > kFarHit * scale)) return;
  const double back = kRefineBack * scale;
  const Ray near{ray.at(hit.t - back), ray.direction, ray.time};
  scene::SurfaceHit again;
  if (!accel_.intersect(near, 0.0, 2 * back, scene::RayKind::shadow, again)) return;
  again.t += hit.t - back;
  hit = again;
}

void PhotonPath::follow(const Ray& ray, Leg leg, const InteriorStack& inside, std::vector<Photon>& out) {
  if (leg.level > limits_.max_trace_level || leg.weight < limits_.adc_bailout) return;
  scene::SurfaceHit hit;
  // Photons pass objects that cast no shadow (POV-Ray trace.cpp, photon rays skip no_shadow objects).
  if (!accel_.intersect(ray, 0.0, math::kInfinity, scene::RayKind::shadow, hit)) return;
  refine_far_hit(ray, hit);
  const scene::Object* object = hit.solid ? hit.solid : hit.object;
  const scene::ObjectPhotons& settings = object->flags.photons;
  if (leg.passed) {
    // Straight from the light (or through pass_through objects) a photon must meet the target it was shot at;
    // anything else ends it (POV-Ray photons.cpp, PhotonTrace::TraceRay).
    if (settings.target.get() == target_)
      hit_target_ = true;
    else if (!settings.pass_through)
      return;
  }
  if (object->interior && inside.contains(object)) leg.power *= interior_fade(*object->interior, hit.t);
  leg.depth += hit.t;
  if (leg.level > 1 && !leg.passed && settings.collect) store(hit.point, -ray.direction, leg, out);

  const Crossing crossing = cross_surface(inside, object);
  if (settings.pass_through) {
    const Ray on{offset_origin(hit.point, ray.direction), ray.direction, ray.time};
    follow(on, Leg{leg.power, leg.weight, leg.level + 1, leg.depth, true}, crossing.next, out);
    return;
  }

  Vec3 raw_normal = hit.normal;
  Vec3 shape_normal = hit.shading_normal;
  if (dot(raw_normal, ray.direction) > 0) {
    raw_normal = -raw_normal;
    shape_normal = -shape_normal;
  }
  if (dot(shape_normal, ray.direction) > 0) shape_normal = raw_normal;
  const material::Texture& texture = *hit.object->texture;
  const Vec3 normal = texture.shading_normal(hit.texture_point, shape_normal, hit.uv);
  const material::Rgbft pigment = texture.pigment_at(hit.texture_point, hit.normal, hit.uv);
  const material::Finish& finish = texture.finish_at(hit.texture_point);

  const double cos_i = -dot(ray.direction, normal);
  // n2 / n1 at this surface, for the Fresnel reflectivity.
  const double relative_ior = 1.0 / crossing.eta;
  const Color reflectivity = finish_reflectivity(finish, pigment.rgb, cos_i, relative_ior);
  Color filter = pigment.rgb * pigment.filter + Color(pigment.transmit);
  if (finish.conserve_energy && finish.reflects()) {
    const Color keep = Color(1) - reflectivity;
    filter *= Color(std::min(1.0, keep.r), std::min(1.0, keep.g), std::min(1.0, keep.b));
  }
  const double trans = std::min(1.0, std::fabs(filter.grey()));

  bool total_internal = false;
  if (photon_switch_on(settings.refraction, light_.photons.refraction) && trans > limits_.adc_bailout) {
    const Leg through{leg.power * filter, leg.weight * filter.max(), leg.level + 1, leg.depth, false};
    const Ray inward_base{offset_origin(hit.point, -raw_normal), ray.direction, ray.time};
    if (std::fabs(crossing.eta - 1) < kEpsilon) {
      follow(inward_base, through, crossing.next, out);
    } else if (const auto dir = refract(ray.direction, normal, crossing.eta)) {
      follow({inward_base.origin, normalize(*dir), ray.time}, through, crossing.next, out);
    } else {
      // Total internal reflection sends the whole photon back, unfiltered.
      total_internal = true;
      const Vec3 mirrored = normalize(math::reflect(ray.direction, normal));
      follow({offset_origin(hit.point, raw_normal), mirrored, ray.time},
             Leg{leg.power, leg.weight, leg.level + 1, leg.depth, false}, inside, out);
    }
  }
  if (!total_internal && photon_switch_on(settings.reflection, light_.photons.reflection) &&
      reflectivity.max() > 0) {
    const Color power = finish.reflection_exponent != 1
                            ? reflectivity * channel_pow(leg.power, finish.reflection_exponent)
                            : reflectivity * leg.power;
    Vec3 mirrored = math::reflect(ray.direction, normal);
    if (dot(mirrored, raw_normal) < 0) mirrored = math::reflect(ray.direction, raw_normal);
    follow({offset_origin(hit.point, raw_normal), normalize(mirrored), ray.time},
           Leg{power, leg.weight * reflectivity.max(), leg.level + 1, leg.depth, false}, inside, out);
  }
}

}  // namespace snell::render::photons
