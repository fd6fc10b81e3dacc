#include "snell/render/whitted.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <span>

#include "snell/accel/indexed_objects.hpp"
#include "snell/geometry/mesh.hpp"
#include "snell/render/area_light.hpp"
#include "snell/render/fog.hpp"
#include "snell/render/glossy.hpp"
#include "snell/render/light_ray.hpp"
#include "snell/render/media.hpp"
#include "snell/render/optics.hpp"
#include "snell/render/shadow_media.hpp"
#include "snell/render/subsurface.hpp"
#include "snell/render/subsurface_povray.hpp"
#include "snell/render/whitted_shading_point.hpp"
#include "snell/scene/csg.hpp"

namespace snell::render {

using math::Color;
using math::Ray;
using math::Vec3;
using scene::RayKind;

namespace {

/// POV-Ray's EPSILON for "nearly zero" comparisons in trace.cpp.
constexpr double kEpsilon = 1e-10;
/// How far a ray that hits nothing is taken to go through fog and media (POV-Ray's BOUND_HUGE).
constexpr double kSkyDepth = 2e10;

/// c^e of a cosine c in [0, 1] (highlights, brilliance), where pow was 3-5% of the render on POV-Ray's
/// metal examples: 0 where it is below exp(-40) = 4e-18, shown without pow by ln c <= c - 1 (so c^e <=
/// exp(-e (1 - c))); whole exponents up to 64 (brilliance 2, roughness 1/20, phong_size 40) by squaring,
/// within a few units in the last place of pow.
double cosine_power(double c, double e) {
  if (e * (1 - c) > 40) return 0.0;
  if (e >= 1 && e <= 64 && e == std::floor(e)) {
    auto n = static_cast<unsigned>(e);
    double result = 1, base = c;
    for (; n > 0; n >>= 1, base *= base)
      if (n & 1) result *= base;
    return result;
  }
  return std::pow(c, e);
}

Color pow_color(const Color& c, double e) {
  return {std::pow(std::max(0.0, c.r), e), std::pow(std::max(0.0, c.g), e), std::pow(std::max(0.0, c.b), e)};
}

/// POV-Ray's empirical Fresnel-like curve used to tint metallic highlights and reflections by the surface
/// colour less at grazing angles (trace.cpp, ComputeMetallic; [DB 9/94]).
double metallic_fresnel(double cos_angle) {
  const double x = std::fabs(std::acos(std::clamp(cos_angle, -1.0, 1.0))) / (0.5 * 3.14159265358979323846);
  const double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
  return std::clamp(f, 0.0, 1.0);
}

Color metallic_tint(double metallic, const Color& pigment, double cos_angle) {
  const double f = metallic_fresnel(cos_angle);
  return Color(1) + (metallic * (1 - f)) * (pigment - Color(1));
}

double max_abs(const Color& c) {
  return std::max(std::fabs(c.r), std::max(std::fabs(c.g), std::fabs(c.b)));
}

/// The scene-level object of a blocking hit, as the accelerator tests it; null for a mesh, whose own
/// triangle tree Embree's native meshes never build (the cache must not build it either).
const scene::Object* cacheable_blocker(const scene::Object* object) {
  if (!object || (object->shape && dynamic_cast<const geometry::Mesh*>(object->shape.get()))) return nullptr;
  return object;
}

const scene::Object* cacheable_blocker(const scene::SurfaceHit& hit) {
  return cacheable_blocker(hit.solid ? hit.solid : hit.object);
}

material::Rgbft pigment_at(const scene::SurfaceHit& hit) {
  // Layered textures composite inside Texture::pigment_at; the top layer's finish lights the result.
  return hit.object->texture->pigment_at(hit.texture_point, hit.normal, hit.uv);
}

/// Whether the surface at `hit` stops light: known from the texture alone where it never transmits.
bool opaque_at(const scene::SurfaceHit& hit) {
  return !hit.object->texture->may_transmit() || !pigment_at(hit).is_transparent();
}

/// Tells the observer the emitted and ambient parts of a surface's own light; `colour` is the pigment
/// scaled by opacity.
void report_own_light(TraceObserver& observer, const Color& colour, const material::Finish& f,
                      const Color& ambient_light) {
  if (!f.emission.is_black()) observer.term(RayTerm::emitted, colour * f.emission, colour * f.emission);
  if (!f.ambient.is_black())
    observer.term(RayTerm::ambient, colour * f.ambient, colour * f.ambient * ambient_light);
}

}  // namespace

WhittedIntegrator::WhittedIntegrator(const scene::Scene& scene, const accel::Accelerator& accelerator)
    : scene_(scene), accel_(accelerator) {
  if (scene.settings.radiosity)
    radiosity_ = std::make_unique<radiosity::Solver>(*scene.settings.radiosity, scene.camera.location,
                                                     scene.memory_budget, scene.settings.max_trace_level);
  for (const material::Media& m : scene.atmosphere) atmosphere_.push_back(&m);
  for (const auto& object : scene.objects)
    if (object->interior && !object->interior->media.empty()) has_interior_media_ = true;
  has_atmosphere_ = has_interior_media_ || !scene.fogs.empty() || !scene.atmosphere.empty();
  opaque_shadows_ = !has_interior_media_ && std::all_of(scene.objects.begin(), scene.objects.end(),
                                                        [](const auto& o) { return stops_all_light(*o); });
  if (has_atmosphere_) camera_inside_ = containing(scene.camera.location);
  if (!opaque_shadows_) shadow_split_ = ShadowSplit::make(scene, accelerator);
  caustics_ = photons::make_caustics(scene, accelerator);
}

// One --stats line for each cache the integrator built: radiosity records, then the photon map.
std::string WhittedIntegrator::summary() const {
  std::string lines = radiosity_ ? radiosity_->summary() : std::string{};
  if (caustics_) {
    if (!lines.empty()) lines.push_back('\n');
    lines.append(caustics_->summary());
  }
  if (shadow_split_) {
    if (!lines.empty()) lines.push_back('\n');
    lines.append(shadow_split_->summary());
  }
  return lines;
}

Color WhittedIntegrator::trace_camera_ray(const Ray& ray, TraceContext& context, double max_distance) const {
  ++context.counters.camera;
  context.time = ray.time;
  if (!has_atmosphere_) return trace(ray, RayKind::camera, 1, 1.0, InteriorStack{}, context, max_distance);
  // POV-Ray starts camera rays inside every object that contains the camera (tracepixel.cpp,
  // InitRayContainerState): fog and media then skip cameras inside solids that are not hollow, and media
  // of a hollow object around the camera show. Done only in scenes with fog or media, where it matters.
  const InteriorStack inside = ray.origin == scene_.camera.location ? camera_inside_ : containing(ray.origin);
  return trace(ray, RayKind::camera, 1, 1.0, inside, context, max_distance);
}

bool WhittedIntegrator::crosses_projection(const scene::Light& light, const Vec3& point,
                                           const LightRay& toward, double time) const {
  const Ray ray{point, toward.direction, time};
  for (const auto& object : light.projected_through) {
    scene::SurfaceHit hit;
    if (object->intersect(ray, 0.0, toward.distance, hit)) return true;
  }
  return false;
}

InteriorStack WhittedIntegrator::containing(const Vec3& point) const {
  InteriorStack inside;
  for (const auto& object : scene_.objects)
    if (object->inside(point)) inside.push(object.get());
  return inside;
}

Color WhittedIntegrator::trace(const Ray& ray, RayKind kind, int level, double weight,
                               const InteriorStack& inside, TraceContext& context,
                               double max_distance) const {
  ObservedRay observed(context.observer, kind, ray, level, weight);
  if (level > scene_.settings.max_trace_level || weight < scene_.settings.adc_bailout) return Color(0);
  scene::SurfaceHit hit;
  const bool found = accel_.intersect(ray, 0.0, max_distance, kind, hit);
  observed.hit(found ? &hit : nullptr);
  const Color seen =
      found ? shade(ray, hit, level, weight, inside, context) : scene_.miss_color(ray.direction);
  context.hit_distance = found ? hit.t : math::kInfinity;  // after shading, which traces on
  if (!has_atmosphere_) return observed.result(seen);
  return observed.result(
      through_atmosphere(ray, found ? hit.t : std::min(kSkyDepth, max_distance), inside, seen, context));
}

Color WhittedIntegrator::through_atmosphere(const Ray& ray, double depth, const InteriorStack& inside,
                                            Color seen, TraceContext& context) const {
  // POV-Ray renders media and fog only along "hollow" rays: inside no solid that is not `hollow`
  // (ray.cpp, Ray::AppendInterior). Media of the solids around the ray come first, then the atmosphere's,
  // then fog (trace.cpp, ComputeLightedTexture and TraceRay).
  for (size_t i = 0; i < inside.size(); ++i)
    if (!inside.at(i)->flags.hollow) return seen;
  const LightSampler light_at = [&](const scene::Light& light, const Vec3& p) {
    const LightRay lr = light_ray(light, p);
    if (max_abs(lr.color) < kEpsilon) return LightAtPoint{};
    if (light.shadowless) return LightAtPoint{lr.color, lr.direction};
    return LightAtPoint{shadowed(light, p, Vec3{0, 0, 0}, lr, lr.color, context), lr.direction};
  };
  std::vector<const material::Media*> media;
  for (size_t i = 0; i < inside.size(); ++i)
    if (const material::Interior* interior = inside.at(i)->interior.get())
      for (const material::Media& m : interior->media) media.push_back(&m);
  const double finite_depth = std::min(depth, kSkyDepth);
  // Radiosity's gather rays see media only with `media on` (POV-Ray 3.7 reference, "media").
  if (context.radiosity_depth > 0 && !radiosity_->settings().media) media.clear();
  if (!media.empty())
    seen = media_along(media, scene_.lights, ray, finite_depth, context.rng, light_at).apply(seen);
  if (!scene_.atmosphere.empty() && (context.radiosity_depth == 0 || radiosity_->settings().media))
    seen = media_along(atmosphere_, scene_.lights, ray, finite_depth, context.rng, light_at).apply(seen);
  return scene_.fogs.empty() ? seen : apply_fogs(scene_.fogs, ray, depth, seen);
}

Color WhittedIntegrator::shadowed(const scene::Light& light, const Vec3& point, const Vec3& normal,
                                  const LightRay& toward, const Color& colour, TraceContext& context) const {
  ObservedRay observed(context.observer, RayKind::shadow, {point, toward.direction, context.time}, 0, 1.0,
                       &light);
  if (!light.projected_through.empty() && !crosses_projection(light, point, toward, context.time))
    return Color(0);
  Color c = shadow_filter(point, normal, toward.direction, toward.distance, colour, context, &light);
  // `media_attenuation`: the atmosphere's media and fog thin the light on its way (trace.cpp,
  // TraceShadowRay and ComputeShadowMedia; fog adds no colour to a shadow ray).
  if (light.media_attenuation && max_abs(c) >= kEpsilon) {
    const Ray shadow_ray{point, toward.direction, context.time};
    const double depth = std::min(toward.distance, kSkyDepth);
    if (!atmosphere_.empty()) c *= media_transmittance(atmosphere_, shadow_ray, depth);
    if (!scene_.fogs.empty()) c *= fogs_along(scene_.fogs, shadow_ray, depth).through;
  }
  return observed.result(c);
}

Color WhittedIntegrator::shade(const Ray& ray, const scene::SurfaceHit& hit, int level, double weight,
                               const InteriorStack& inside, TraceContext& context,
                               const material::Texture* texture_entry) const {
  const material::Texture& texture = texture_entry ? *texture_entry : *hit.object->texture;
  // One frame of shadow-tested lights for this point, shared by the entries of an averaged texture.
  std::optional<LitLightsFrame> lit_frame;
  if (!texture_entry) lit_frame.emplace(context.lit_lights, scene_.lights.size());
  const int frame = lit_frame ? lit_frame->frame() : context.lit_lights.innermost();
  if (!texture.averaged.empty()) return shade_averaged(ray, hit, texture, level, weight, inside, context);
  ShadingPoint sp;
  sp.lit_frame = frame;
  sp.ray = &ray;
  sp.hit = &hit;
  sp.texture = &texture;
  sp.finish = &texture.finish_at(hit.texture_point, hit.normal, ray.direction);
  sp.point = hit.point;
  sp.raw_normal = hit.normal;
  Vec3 shape_normal = hit.shading_normal;
  // POV-Ray shades the side facing the viewer (trace.cpp, ComputeOneTextureColour flips the normal).
  if (dot(sp.raw_normal, ray.direction) > 0) {
    sp.raw_normal = -sp.raw_normal;
    shape_normal = -shape_normal;
  }
  // An interpolated normal (smooth triangles) that faces away falls back to the true one.
  if (dot(shape_normal, ray.direction) > 0) shape_normal = sp.raw_normal;
  // The texture's normal then bends the oriented normal, as POV-Ray perturbs its flipped raw normal
  // (trace.cpp: layNormal = rawnormal; Perturb_Normal); a bump may face away, and it keeps it.
  // The top layer's own normal and pigment; layers below are lit on their own (layered_shading.cpp).
  sp.normal = texture.own_shading_normal(hit.texture_point, shape_normal, hit.uv);
  sp.pigment = texture.own_pigment_at(hit.texture_point, hit.normal, hit.uv, ray.direction);
  sp.observer = context.observer;
  sp.highlights = context.radiosity_depth == 0;
  const material::Rgbft& pc = sp.pigment;
  const material::Finish& f = *sp.finish;
  sp.opacity = opacity_of(pc, scene_.settings.language_version);

  // Interiors are tracked per solid: the CSG object for a hit on one of its children.
  const scene::Object* object = hit.solid ? hit.solid : hit.object;
  const double object_ior = ior_of(object->interior ? object : hit.object);
  // Relative ior n2/n1 for Fresnel reflection (trace.cpp, ComputeRelativeIOR).
  double relative_ior = object_ior;
  if (!inside.empty()) {
    if (inside.contains(object))
      relative_ior = inside.size() == 1 ? 1.0 / object_ior : ior_of(inside.back()) / object_ior;
    else
      relative_ior = object_ior / ior_of(inside.back());
  }

  double reflect_weight = weight;
  const Color reflectivity = reflectivity_of(sp, relative_ior, reflect_weight);
  Color result = lit_entries(sp, shape_normal, object, relative_ior, level, weight, inside, context);

  // Light through the surface (trace.cpp: filCol, trans).
  Color filter = transmitted_color(pc);
  if (f.conserve_energy && f.reflects()) {
    const Color keep = Color(1) - reflectivity;
    filter *= Color(std::min(1.0, keep.r), std::min(1.0, keep.g), std::min(1.0, keep.b));
  }
  if (texture.below)
    result += lower_layers(sp, shape_normal, object, relative_ior, level, weight, inside, context, filter);
  const double trans = std::min(1.0, std::fabs(filter.grey()));

  bool tir = false;
  if (trans > scene_.settings.adc_bailout) {
    const double t_weight = weight * max_abs(filter);
    // Which medium the ray goes into (trace.cpp, ComputeRefraction: nested solids count as outside).
    InteriorStack next = inside;
    double eta;  // n1 / n2
    if (inside.empty()) {
      next.push(object);
      eta = 1.0 / object_ior;
    } else if (object == inside.back()) {
      next.remove(object);
      eta = object_ior / (next.empty() ? 1.0 : ior_of(next.back()));
    } else if (next.remove(object)) {
      eta = 1.0;
    } else {
      eta = ior_of(inside.back()) / object_ior;
      next.push(object);
    }
    Color through;
    Color through_filter = filter;
    if (std::fabs(eta - 1) < kEpsilon) {
      ++context.counters.refracted;
      through = trace({offset_origin(sp.point, -sp.raw_normal), ray.direction, ray.time}, RayKind::refraction,
                      level + 1, t_weight, next, context);
    } else if (f.transmission_blur > 0) {
      // Frosted glass (render/glossy.hpp): microfacets past their critical angle reflect, unfiltered.
      tir = !refract(ray.direction, sp.normal, eta);
      const RoughTransmission rough = rough_transmission(
          {ray.direction, sp.normal, sp.raw_normal, f.transmission_blur}, eta,
          rough_sample_count(f.transmission_samples, level), context.rng,
          [&](const Vec3& dir) {
            ++context.counters.refracted;
            return trace({offset_origin(sp.point, -sp.raw_normal), dir, ray.time}, RayKind::refraction,
                         level + 1, t_weight, next, context);
          },
          [&](const Vec3& dir) { return trace_reflection(sp, dir, level, t_weight, inside, context); });
      through = rough.refracted * filter + rough.reflected;
      through_filter = Color(1);
    } else if (auto dir = refract(ray.direction, sp.normal, eta)) {
      ++context.counters.refracted;
      through = trace({offset_origin(sp.point, -sp.raw_normal), normalize(*dir), ray.time},
                      RayKind::refraction, level + 1, t_weight, next, context);
    } else {
      tir = true;
      if (sp.observer) sp.observer->total_internal_reflection();
      through = reflect(sp, level, t_weight, inside, context);
    }
    // Interior fade over the distance travelled inside this object (POV-Ray 3.7 reference, "Interior").
    Color fade(1);
    const material::Interior* interior = object->interior.get();
    if (interior && inside.contains(object) && std::fabs(interior->fade_distance) > kEpsilon) {
      const double depth = hit.t / interior->fade_distance;
      const Color fc = interior->fade_color;
      if (interior->fade_power >= 1000) {
        fade = {std::exp(-(1 - fc.r) * depth), std::exp(-(1 - fc.g) * depth), std::exp(-(1 - fc.b) * depth)};
      } else {
        const double a = 1 + std::pow(depth, interior->fade_power);
        fade = fc + (Color(1) - fc) / a;
      }
    }
    const Color through_weight = tir ? fade : fade * through_filter;
    result += through_weight * through;
    if (sp.observer) sp.observer->term(RayTerm::transmitted, through_weight, through_weight * through);
  }

  if (!tir && f.reflects() && !reflectivity.is_black()) {
    const Color seen = reflect(sp, level, reflect_weight, inside, context);
    const Color reflected =
        reflectivity * (f.reflection_exponent != 1 ? pow_color(seen, f.reflection_exponent) : seen);
    result += reflected;
    if (sp.observer) sp.observer->term(RayTerm::reflected, reflectivity, reflected);
  }
  return result;
}

Color WhittedIntegrator::reflectivity_of(const ShadingPoint& sp, double relative_ior, double& weight) const {
  // Reflectivity (trace.cpp, ComputeReflectivity / ComputeMetallic).
  const material::Finish& f = *sp.finish;
  if (!f.reflects()) return Color(0);
  const double cos_i = -dot(sp.ray->direction, sp.normal);
  Color reflectivity;
  if (f.reflection_fresnel) {
    const double fr = std::clamp(fresnel_dielectric(cos_i, 1.0, relative_ior), 0.0, 1.0);
    reflectivity = fr * f.reflection_max + (1 - fr) * f.reflection_min;
    weight *= reflectivity.max();
  } else {
    weight *= std::max(f.reflection_max.max(), f.reflection_min.max());
    const double frac = std::fabs(f.reflection_falloff - 1) > kEpsilon
                            ? std::pow(std::max(0.0, 1 - cos_i), f.reflection_falloff)
                            : 1 - cos_i;
    if (std::fabs(frac) < kEpsilon)
      reflectivity = f.reflection_min;
    else if (std::fabs(frac - 1) < kEpsilon)
      reflectivity = f.reflection_max;
    else
      reflectivity = frac * f.reflection_max + (1 - frac) * f.reflection_min;
  }
  if (f.reflection_metallic > 0) reflectivity *= metallic_tint(f.reflection_metallic, sp.pigment.rgb, cos_i);
  return reflectivity;
}

Color WhittedIntegrator::lit_entries(const ShadingPoint& sp, const Vec3& shape_normal,
                                     const scene::Object* object, double relative_ior, int level,
                                     double weight, const InteriorStack& inside,
                                     TraceContext& context) const {
  // A point between two entries of a texture map: POV-Ray lights each entry with its own pigment, normal
  // and finish and blends the lit colours (trace.cpp, ComputeTextureColour); one blended pigment under
  // the heavier entry's finish lit grass like sand where a slope map fades one into the other.
  // Most textures are no map: they go straight on, without clearing the two entries (a `rep stos`, two
  // thirds of this function in pigmap.pov's profile).
  if (!sp.texture->selector) return own_light(sp, object, relative_ior, level, weight, inside, context);
  material::Texture::MapEntry entries[2];
  if (!sp.texture->map_entries_at(sp.hit->texture_point, sp.hit->normal, shape_normal, sp.hit->uv,
                                  sp.ray->direction, entries))
    return own_light(sp, object, relative_ior, level, weight, inside, context);
  Color result(0);
  for (const material::Texture::MapEntry& e : entries) {
    ShadingPoint entry = sp;
    entry.pigment = e.pigment;
    entry.finish = e.finish;
    entry.normal = e.normal;
    entry.opacity = opacity_of(e.pigment, scene_.settings.language_version);
    result += e.weight * own_light(entry, object, relative_ior, level, weight * e.weight, inside, context);
  }
  return result;
}

Color WhittedIntegrator::own_light(const ShadingPoint& sp, const scene::Object* object, double relative_ior,
                                   int level, double weight, const InteriorStack& inside,
                                   TraceContext& context) const {
  const material::Finish& f = *sp.finish;
  const material::Rgbft& pc = sp.pigment;
  // Emission and classic ambient, then the light sources.
  // With radiosity, 3.7 scenes drop `ambient` and gather the ambient light (trace.cpp,
  // ComputeLightedTexture), skipped where it could not reach adc_bailout.
  const bool classic_ambient = !radiosity_ || scene_.settings.language_version < 3.7;
  const Color ambient = classic_ambient ? f.ambient * scene_.settings.ambient_light : Color(0);
  Color result = pc.rgb * (f.emission + ambient) * sp.opacity;
  if (sp.observer) report_own_light(*sp.observer, pc.rgb * sp.opacity, f, scene_.settings.ambient_light);
  const double most_indirect = pc.rgb.grey() * sp.opacity * f.diffuse;
  if (radiosity_ && radiosity_->gathers_at(context.radiosity_depth) &&
      most_indirect > scene_.settings.adc_bailout) {
    const Vec3 around = radiosity_->settings().normal ? sp.normal : sp.raw_normal;
    const Color gathered = radiosity_->ambient(
        sp.point, around, weight * most_indirect, context, [&](const Vec3& dir, int at_level, double w) {
          return trace({offset_origin(sp.point, around), dir, sp.ray->time}, RayKind::reflection, at_level, w,
                       inside, context);
        });
    result += pc.rgb * gathered * (f.diffuse * sp.opacity);
  }
  if (f.diffuse != 0 || f.specular != 0 || f.phong != 0) result += direct_light(sp, context);
  if (caustics_ && (f.diffuse != 0 || f.specular != 0 || f.phong != 0))
    result +=
        caustics_->radiance(*object, sp.point, sp.raw_normal, sp.normal,
                            [&](const Vec3& dir, const Color& c) { return surface_response(sp, dir, c); });
  if (f.subsurface) result += subsurface_light(sp, object, relative_ior, context);
  return result;
}

Color WhittedIntegrator::reflect(const ShadingPoint& sp, int level, double weight,
                                 const InteriorStack& inside, TraceContext& context) const {
  const Vec3& d = sp.ray->direction;
  if (sp.finish->reflection_blur > 0)
    return glossy_reflection(
        {d, sp.normal, sp.raw_normal, sp.finish->reflection_blur},
        rough_sample_count(sp.finish->reflection_samples, level), context.rng,
        [&](const Vec3& r) { return trace_reflection(sp, r, level, weight, inside, context); });
  Vec3 r = math::reflect(d, sp.normal);
  // A perturbed normal can send the ray into the surface; fold it back as POV-Ray does (trace.cpp,
  // ComputeReflection, "Reflection bugfix").
  const double n = dot(r, sp.raw_normal);
  if (n < 0) r = dot(r, sp.normal) < 0 ? math::reflect(d, sp.raw_normal) : r - 2 * n * sp.raw_normal;
  return trace_reflection(sp, normalize(r), level, weight, inside, context);
}

Color WhittedIntegrator::trace_reflection(const ShadingPoint& sp, const Vec3& direction, int level,
                                          double weight, const InteriorStack& inside,
                                          TraceContext& context) const {
  ++context.counters.reflected;
  return trace({offset_origin(sp.point, sp.raw_normal), direction, sp.ray->time}, RayKind::reflection,
               level + 1, weight, inside, context);
}

template <class Test>
Color WhittedIntegrator::shadow_tested(const ShadingPoint& sp, const scene::Light& light,
                                       TraceContext& context, Test&& test) const {
  if (sp.lit_frame < 0) return test();
  const auto index = static_cast<size_t>(&light - scene_.lights.data());
  if (const LitLights::Entry& known = context.lit_lights.lookup(sp.lit_frame, index); known.tested)
    return known.colour;
  const Color c = test();  // may shade other points, which may grow the storage: look the entry up again
  LitLights::Entry& entry = context.lit_lights.lookup(sp.lit_frame, index);
  entry.tested = true;
  entry.colour = c;
  return c;
}

Color WhittedIntegrator::direct_light(const ShadingPoint& sp, TraceContext& context) const {
  const bool double_illuminate = sp.hit->object->flags.double_illuminate;
  // Radiosity's gather rays see an area light as a point light at its centre (POV-Ray 3.7 radiosity.cpp,
  // GetRadiosityQualityFlags clears Q_AREA_LIGHT): the light it bounces is an average anyway, and a full
  // grid of shadow rays behind every gather ray was most of a radiosity scene's time.
  const bool area_lights = context.radiosity_depth == 0;
  Color sum;
  for (const scene::Light& light : scene_.lights) {
    const bool area = light.area && area_lights;
    if (area && light.area_illumination) {
      sum += full_area_light(sp, light, context);
      continue;
    }
    const LightRay lr = light_ray(light, sp.point);
    if (max_abs(lr.color) < kEpsilon) continue;
    const double cos_l = dot(sp.normal, lr.direction);
    if (!double_illuminate && cos_l < kEpsilon) continue;
    Color lc = lr.color;
    if (!light.shadowless) {
      lc = shadow_tested(sp, light, context, [&] {
        return area ? area_shadow(sp, light, lr, context)
                    : shadowed(light, sp.point, sp.raw_normal, lr, lr.color, context);
      });
      if (max_abs(lc) < kEpsilon) continue;
    }
    sum += surface_response(sp, lr.direction, lc, !light.shadowless);
  }
  return sum;
}

Color WhittedIntegrator::area_shadow(const ShadingPoint& sp, const scene::Light& light,
                                     const LightRay& centre, TraceContext& context) const {
  const auto [axis1, axis2] = area_light_axes(light, centre.direction);
  return area_light_shadow(light, axis1, axis2, context.rng, [&](const Vec3& offset) {
    return shadowed(light, sp.point, sp.raw_normal, light_direction(light, sp.point, offset), centre.color,
                    context);
  });
}

Color WhittedIntegrator::full_area_light(const ShadingPoint& sp, const scene::Light& light,
                                         TraceContext& context) const {
  // `area_illumination` (POV-Ray 3.7 trace.cpp, ComputeFullAreaDiffuseLight): shadows as usual, then every
  // grid point lights the surface as a point light of 1/(n1 n2) the colour, with its own direction, cone
  // and fade. There is no cut-off for lights behind the surface before the shadow test.
  LightRay centre = light_direction(light, sp.point);
  centre.color = light.color;
  Color lc = light.color;
  if (!light.shadowless)
    lc = shadow_tested(sp, light, context, [&] { return area_shadow(sp, light, centre, context); });
  if (max_abs(lc) < kEpsilon) return Color(0);
  const auto [axis1, axis2] = area_light_axes(light, centre.direction);
  const Color part = lc / static_cast<double>(light.size1 * light.size2);
  const bool double_illuminate = sp.hit->object->flags.double_illuminate;
  Color sum;
  for (int v = 0; v < light.size2; ++v)
    for (int u = 0; u < light.size1; ++u) {
      const Vec3 offset = area_light_sample_offset(light, axis1, axis2, u, v, context.rng);
      const LightRay r = light_direction(light, sp.point, offset);
      if (!double_illuminate && dot(sp.normal, r.direction) < kEpsilon) continue;
      sum +=
          surface_response(sp, r.direction, part * light_attenuation(light, sp.point, r), !light.shadowless);
    }
  return sum;
}

Color WhittedIntegrator::surface_response(const ShadingPoint& sp, const Vec3& to_light, const Color& lc,
                                          bool highlights) const {
  const material::Finish& f = *sp.finish;
  const Color& pigment = sp.pigment.rgb;
  const Vec3& eye = sp.ray->direction;
  const double cos_l = dot(sp.normal, to_light);
  Color sum;
  // Diffuse (trace.cpp, ComputeDiffuseColour): |cos|^brilliance, reduced by the surface's opacity. A
  // subsurface finish replaces it by the dipole (subsurface_light).
  if (f.diffuse > 0 && !f.subsurface) {
    const double c = std::fabs(cos_l);
    const double intensity = (f.brilliance != 1 ? cosine_power(c, f.brilliance) : c) * f.diffuse * sp.opacity;
    sum += intensity * pigment * lc;
    if (sp.observer) sp.observer->term(RayTerm::diffuse, intensity * pigment, intensity * pigment * lc);
  }
  // Phong: the mirror direction of the eye against the light direction, to the power phong_size.
  // A shadowless light gives none (trace.cpp, ComputeOneDiffuseLight skips them for fill lights).
  highlights = highlights && sp.highlights;
  if (f.phong > 0 && highlights) {
    const double c = dot(math::reflect(eye, sp.normal), to_light);
    if (c > 0) {
      const double intensity = f.phong * cosine_power(c, f.phong_size);
      const Color phong = intensity * (f.metallic > 0 ? lc * metallic_tint(f.metallic, pigment, cos_l) : lc);
      sum += phong;
      if (sp.observer) sp.observer->term(RayTerm::phong, Color(intensity), phong);
    }
  }
  // Specular: Blinn's halfway vector, exponent 1/roughness.
  if (f.specular > 0 && highlights) {
    const Vec3 h = 0.5 * (to_light - eye);
    const double hl = length(h);
    if (hl > 0) {
      const double c = dot(h, sp.normal) / hl;
      if (c > 0) {
        const double intensity = f.specular * cosine_power(c, 1.0 / f.roughness);
        const Color specular =
            intensity * (f.metallic > 0 ? lc * metallic_tint(f.metallic, pigment, cos_l) : lc);
        sum += specular;
        if (sp.observer) sp.observer->term(RayTerm::specular, Color(intensity), specular);
      }
    }
  }
  return sum;
}

Color WhittedIntegrator::subsurface_light(const ShadingPoint& sp, const scene::Object* solid,
                                          double relative_ior, TraceContext& context) const {
  // POV-Ray's `translucency` finishes follow POV-Ray's own estimate; snell's measured materials the dipole.
  if (!sp.finish->subsurface_material) return povray_subsurface_light(sp, solid, relative_ior, context);
  // Light entering around the point from the light sources (POV-Ray 3.7: ComputeSubsurfaceScattering's
  // diffuse part; area lights count from their centre here).
  SubsurfaceQuery query;
  query.solid = solid;
  query.point = sp.point;
  query.normal = sp.raw_normal;
  query.dipole = finish_dipole(*sp.finish, sp.pigment.rgb, std::max(relative_ior, 1.0 / relative_ior));
  query.mm_per_unit = scene_.settings.mm_per_unit;
  query.samples = scene_.settings.subsurface_samples;
  const auto irradiance = [&](const Vec3& point, const Vec3& normal) {
    Color e;
    for (const scene::Light& light : scene_.lights) {
      const LightRay lr = light_ray(light, point);
      const double cos_l = dot(normal, lr.direction);
      if (cos_l <= 0 || max_abs(lr.color) < kEpsilon) continue;
      e += cos_l * (light.shadowless ? lr.color : shadowed(light, point, normal, lr, lr.color, context));
    }
    return e;
  };
  return subsurface_radiance(query, accel_, context.rng, irradiance) * sp.opacity;
}

Color WhittedIntegrator::povray_subsurface_light(const ShadingPoint& sp, const scene::Object* solid,
                                                 double relative_ior, TraceContext& context) const {
  PovraySubsurfaceQuery query;
  query.solid = solid;
  query.point = sp.point;
  query.normal = sp.raw_normal;
  query.to_viewer = -sp.ray->direction;
  query.reflectance = sp.pigment.rgb * sp.finish->diffuse;
  query.translucency = sp.finish->subsurface_translucency;
  query.ior = std::max(relative_ior, 1.0 / relative_ior);
  query.mm_per_unit = scene_.settings.mm_per_unit;
  query.diffuse_samples = scene_.settings.subsurface_samples;
  query.single_samples = scene_.settings.subsurface_single_samples;
  // One entry per light, in scene order (the single-scattering term pairs them up by index).
  const auto lights = [&](const Vec3& point, const Vec3& normal, std::vector<IncidentLight>& out) {
    for (const scene::Light& light : scene_.lights) {
      const LightRay lr = light_ray(light, point);
      const Vec3 facing = dot(normal, lr.direction) >= 0 ? normal : -normal;
      const bool lit = max_abs(lr.color) >= kEpsilon;
      out.push_back({lr.direction, !lit || light.shadowless
                                       ? (lit ? lr.color : Color(0))
                                       : shadowed(light, point, facing, lr, lr.color, context)});
    }
  };
  return povray_subsurface_radiance(query, accel_, context.rng, lights) * sp.opacity;
}

TraceContext::ShadowBlocker* WhittedIntegrator::cached_blocker(const scene::Light* source,
                                                               TraceContext& context) const {
  if (!source || context.observer) return nullptr;
  const std::span<const scene::Light> lights(scene_.lights);
  // By address, so a light that is not one of the scene's (a test's own) has no entry.
  if (std::less<>{}(source, lights.data()) || !std::less<>{}(source, lights.data() + lights.size()))
    return nullptr;
  if (context.shadow_blockers.size() != lights.size()) [[unlikely]]
    context.shadow_blockers.assign(lights.size(), {});
  return &context.shadow_blockers[static_cast<size_t>(source - lights.data())];
}

Color WhittedIntegrator::shadow_filter(const Vec3& point, const Vec3& normal, const Vec3& dir,
                                       double distance, Color light, TraceContext& context,
                                       const scene::Light* source) const {
  // Start on the side of the surface the light is on, so a surface never shadows itself.
  Vec3 origin = offset_origin(point, dot(normal, dir) >= 0 ? normal : -normal);
  double remaining = distance - dot(origin - point, dir);
  ++context.counters.shadow;
  // Any opaque blocker makes the light black, whatever else lies on the way, so the last one this light
  // met is tried alone before the whole scene. (Not while an observer records the blockers in order.)
  TraceContext::ShadowBlocker* cached = cached_blocker(source, context);
  // Filled by each test that finds one; kept per thread, as clearing a fresh one for every shadow ray cost
  // more than some of the tests (nothing below traces another shadow ray while it is in use).
  thread_local scene::SurfaceHit hit;
  if (cached && cached->object) {
    const math::Ray ray{origin, dir, context.time};
    // Where the blocker stops all light, a crossing is enough and its hit is not built.
    const scene::Object& blocker = *cached->object;
    if (cached->stops_all_light
            ? accel::object_blocks(blocker, ray, 0.0, remaining, RayKind::shadow)
            : accel::test_object(blocker, ray, 0.0, remaining, RayKind::shadow, hit) && opaque_at(hit))
      return Color(0);
  }
  // Where nothing can let light through, any blocker will do: the walk stops at the first one found and
  // no hit is built (an observer wants every blocker in order, so it takes the loop below).
  if (opaque_shadows_ && !context.observer) {
    const scene::Object* blocker =
        accel_.occluder({origin, dir, context.time}, 0.0, remaining, RayKind::shadow);
    if (!blocker) {
      // The light reached the point, so it empties its cache: the points after it are likely lit too (the
      // shadow's edge was crossed), and trying the last blocker first would cost each of them a test that
      // fails; the next shadowed point finds a blocker in the walk above and caches it again. In
      // pigmap.pov most points are lit and those failing tests were 3.4% of the render's instructions.
      // (Not on the path below for scenes with transparent objects: in crystal.pov, light through glass,
      // forgetting there cost 1.7% more than it saved.)
      if (cached) cached->object = nullptr;
      return light;
    }
    if (cached) *cached = {cacheable_blocker(blocker), true};
    return Color(0);
  }
  // Media inside the solids crossed thin the light whatever the light's media flags (POV-Ray 3.7 trace.cpp,
  // ComputeShadowColour; those flags govern the atmosphere only).
  const bool thinned_by_media = has_interior_media_;
  // Built only for scenes with interior media: it is a few hundred bytes to clear for every shadow ray.
  std::optional<ShadowMedia> media;
  if (thinned_by_media) media.emplace(math::Ray{point, dir, context.time});
  // Where the scene is split (shadow_split.hpp), any opaque crossing settles the ray, and the walk below
  // then meets only the transparent objects. (Not for an observer, which wants every blocker in order.)
  const accel::Accelerator* walked = &accel_;
  if (shadow_split_ && !context.observer) {
    const math::Ray ray{origin, dir, context.time};
    if (const scene::Object* blocker =
            shadow_split_->opaque().occluder(ray, 0.0, remaining, RayKind::shadow)) {
      if (cached) *cached = {cacheable_blocker(blocker), true};  // from the opaque objects
      return Color(0);
    }
    walked = &shadow_split_->passing();
  }
  // Pass through transparent blockers, tinting by each one's transmitted colour (trace.cpp,
  // TracePointLightShadowRay / ComputeShadowColour). Bounded so that coincident surfaces cannot loop.
  for (int crossings = 0; crossings < 64 && remaining > 0; ++crossings) {
    if (!walked->intersect({origin, dir, context.time}, 0.0, remaining, RayKind::shadow, hit)) break;
    // A texture that never transmits stops the ray without its pigment being evaluated (an observer wants
    // the colour). Rgbft{} is opaque black.
    const bool known_opaque = !context.observer && !hit.object->texture->may_transmit();
    const material::Rgbft c = known_opaque ? material::Rgbft{} : pigment_at(hit);
    if (context.observer) context.observer->shadow_blocker(hit, !c.is_transparent());
    if (!c.is_transparent()) {
      // May let light through elsewhere (the split's walk meets only such objects): tested with its hit.
      if (cached) *cached = {cacheable_blocker(hit), false};
      return Color(0);
    }
    if (caustics_ && source && caustics_->replaces_shadow(*source, hit.solid ? *hit.solid : *hit.object))
      return Color(0);
    light *= transmitted_color(c);
    if (max_abs(light) < scene_.settings.adc_bailout) return Color(0);
    const scene::Object& solid = hit.solid ? *hit.solid : *hit.object;
    if (media && ShadowMedia::has_media(solid)) media->cross(solid, dot(hit.point - point, dir), hit.normal);
    const Vec3 side = dot(hit.normal, dir) >= 0 ? hit.normal : -hit.normal;
    const Vec3 next = offset_origin(hit.point, side);
    remaining -= dot(next - origin, dir);
    origin = next;
  }
  return media ? light * media->transmittance(distance) : light;
}

}  // namespace snell::render
