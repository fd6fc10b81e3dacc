#pragma once
// POV-Ray 3.7's classic ray tracer (source/core/render/trace.cpp: ComputeLightedTexture and the lighting
// functions it calls), rewritten for snell's scene model: ambient/emission, diffuse with brilliance, phong,
// specular, metallic highlights, reflection (min/max, fresnel, falloff, exponent, metallic), refraction
// with total internal reflection, filter/transmit and filtered shadows, termination by max_trace_level
// and adc_bailout. Area lights with POV-Ray's adaptive grid; caustics from a photon map.
#include <cmath>
#include <memory>
#include <vector>

#include "snell/material/texture.hpp"
#include "snell/render/integrator.hpp"
#include "snell/render/interior_stack.hpp"
#include "snell/render/light_ray.hpp"
#include "snell/render/photons/caustics.hpp"
#include "snell/render/radiosity/solver.hpp"
#include "snell/render/shadow_split.hpp"

namespace snell::render {

class WhittedIntegrator final : public Integrator {
 public:
  WhittedIntegrator(const scene::Scene& scene, const accel::Accelerator& accelerator);

  math::Color trace_camera_ray(const math::Ray& ray, TraceContext& context,
                               double max_distance = math::kInfinity) const override;
  std::string_view name() const override { return "whitted"; }
  // Radiosity's pretrace, per-tile records and statistics (whitted_radiosity.cpp).
  void prepare(const scene::Camera& camera, int width, int height, const PixelRect& region,
               double time) override;
  void begin_tile(TraceContext& context) const override;
  bool samples_depend_on_tile() const override { return radiosity_ != nullptr; }
  std::string summary() const override;

  /// Colour seen along `ray` (unit direction) at recursion `level` (camera rays are level 1), with the
  /// ray's contribution `weight` to the pixel: black past max_trace_level or below adc_bailout.
  /// `max_distance` limits what the ray sees (camera rays of a mesh camera).
  math::Color trace(const math::Ray& ray, scene::RayKind kind, int level, double weight,
                    const InteriorStack& inside, TraceContext& context,
                    double max_distance = math::kInfinity) const;

 private:
  struct ShadingPoint;
  /// `texture`: the texture to light, when not the hit object's own (an entry of an averaged texture).
  math::Color shade(const math::Ray& ray, const scene::SurfaceHit& hit, int level, double weight,
                    const InteriorStack& inside, TraceContext& context,
                    const material::Texture* texture = nullptr) const;
  /// An averaged texture: each entry lit in full, the weighted mean (average_shading.cpp).
  math::Color shade_averaged(const math::Ray& ray, const scene::SurfaceHit& hit,
                             const material::Texture& texture, int level, double weight,
                             const InteriorStack& inside, TraceContext& context) const;
  /// How much the surface reflects (POV-Ray's reflectivity with fresnel, falloff and metallic); scales
  /// `weight` by the most it can reflect.
  math::Color reflectivity_of(const ShadingPoint& sp, double relative_ior, double& weight) const;
  /// The surface's own light towards the eye: emission, ambient or radiosity, the light sources.
  /// own_light, or for a point between two texture map entries their own lights blended.
  math::Color lit_entries(const ShadingPoint& sp, const math::Vec3& shape_normal, const scene::Object* object,
                          double relative_ior, int level, double weight, const InteriorStack& inside,
                          TraceContext& context) const;
  math::Color own_light(const ShadingPoint& sp, const scene::Object* object, double relative_ior, int level,
                        double weight, const InteriorStack& inside, TraceContext& context) const;
  /// Layers under the top one of a layered texture, each lit with its own finish and normal and seen
  /// through the layers above (`filter`, which they narrow in turn); their reflections included.
  math::Color lower_layers(const ShadingPoint& top, const math::Vec3& shape_normal,
                           const scene::Object* object, double relative_ior, int level, double weight,
                           const InteriorStack& inside, TraceContext& context, math::Color& filter) const;
  math::Color direct_light(const ShadingPoint& sp, TraceContext& context) const;
  /// `light`'s colour at the shading point after `test()`, its shadow test, run once per shading point
  /// however many layers and texture entries light it (lit_lights.hpp).
  template <class Test>
  math::Color shadow_tested(const ShadingPoint& sp, const scene::Light& light, TraceContext& context,
                            Test&& test) const;
  /// Mean light through an area light's shadow rays; `centre` is the ray to its centre, with its colour.
  math::Color area_shadow(const ShadingPoint& sp, const scene::Light& light, const LightRay& centre,
                          TraceContext& context) const;
  /// An `area_illumination` light: each grid point shades the surface from its own direction.
  math::Color full_area_light(const ShadingPoint& sp, const scene::Light& light, TraceContext& context) const;
  /// Diffuse, phong and specular light reflected towards the eye from light `lc` arriving along `to_light`;
  /// phong and specular only with `highlights` (not from shadowless lights, POV-Ray's fill lights).
  math::Color surface_response(const ShadingPoint& sp, const math::Vec3& to_light, const math::Color& lc,
                               bool highlights = true) const;
  /// Diffuse light re-emitted by a `subsurface` finish (render/subsurface.hpp), replacing the diffuse term.
  math::Color subsurface_light(const ShadingPoint& sp, const scene::Object* solid, double relative_ior,
                               TraceContext& context) const;
  /// The same for POV-Ray's `translucency` finishes, as POV-Ray estimates it (subsurface_povray.hpp).
  math::Color povray_subsurface_light(const ShadingPoint& sp, const scene::Object* solid, double relative_ior,
                                      TraceContext& context) const;
  /// `seen` at `depth` along the ray as it reaches the ray's origin through media and fog.
  math::Color through_atmosphere(const math::Ray& ray, double depth, const InteriorStack& inside,
                                 math::Color seen, TraceContext& context) const;
  /// `colour` from `light` after shadows along `toward` and, with media_attenuation, the atmosphere.
  math::Color shadowed(const scene::Light& light, const math::Vec3& point, const math::Vec3& normal,
                       const LightRay& toward, const math::Color& colour, TraceContext& context) const;
  /// The shadow cache entry of `source` in this thread's context (TraceContext::shadow_blockers); null
  /// when the ray has no scene light or an observer is watching.
  TraceContext::ShadowBlocker* cached_blocker(const scene::Light* source, TraceContext& context) const;
  /// Light reaching `point` from direction `dir` within `distance`, tinted by transparent blockers.
  math::Color shadow_filter(const math::Vec3& point, const math::Vec3& normal, const math::Vec3& dir,
                            double distance, math::Color light, TraceContext& context,
                            const scene::Light* source = nullptr) const;
  /// Mirror reflection, or glossy reflection when the finish has `blur`.
  math::Color reflect(const ShadingPoint& sp, int level, double weight, const InteriorStack& inside,
                      TraceContext& context) const;
  /// Colour seen along a reflected ray leaving the shading point in unit `direction`.
  math::Color trace_reflection(const ShadingPoint& sp, const math::Vec3& direction, int level, double weight,
                               const InteriorStack& inside, TraceContext& context) const;

  const scene::Scene& scene_;
  const accel::Accelerator& accel_;
  /// Whether the ray from `point` towards the light crosses its projected_through object.
  bool crosses_projection(const scene::Light& light, const math::Vec3& point, const LightRay& toward,
                          double time) const;
  /// The scene's objects that contain `point`, in scene order.
  InteriorStack containing(const math::Vec3& point) const;

  std::vector<const material::Media*> atmosphere_;
  bool has_interior_media_ = false;
  /// No surface lets light through and no solid holds media: a shadow ray is blocked by any hit.
  bool opaque_shadows_ = false;
  /// Fog or media anywhere: camera rays then start inside the objects around the camera.
  bool has_atmosphere_ = false;
  InteriorStack camera_inside_;
  /// Set when the scene has `radiosity {}`: it then replaces the ambient term.
  std::unique_ptr<radiosity::Solver> radiosity_;
  /// Set when the scene has `photons {}`: the caustic photon map (render/photons/caustics.hpp).
  std::unique_ptr<photons::Caustics> caustics_;
  /// Set where some surfaces let light through and others stop it all (render/shadow_split.hpp).
  std::unique_ptr<ShadowSplit> shadow_split_;
};

/// Origin for a ray leaving surface point `p` towards the side `side` points to: moved off the surface by
/// an epsilon that scales with the magnitude of p, since the hit point's floating-point error does.
/// Inline: every shadow ray starts here, and the call cost as much as the work.
inline math::Vec3 offset_origin(const math::Vec3& p, const math::Vec3& side) {
  // Intersection routines in double lose a few digits (quadric roots, transforms), so 1e-9 of the
  // coordinates' magnitude stays well above their error and far below detail.
  constexpr double kRelativeOffset = 1e-9, kAbsoluteOffset = 1e-9;
  const double scale = kAbsoluteOffset + kRelativeOffset * max_component(abs(p));
  // Callers mostly pass unit normals already: those skip the square root and division.
  const double length2 = dot(side, side);
  if (std::fabs(length2 - 1) < 1e-12 || length2 == 0) return p + side * scale;
  return p + side * (scale / std::sqrt(length2));
}

}  // namespace snell::render
