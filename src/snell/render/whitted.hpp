#pragma once
// POV-Ray 3.7's classic ray tracer (source/core/render/trace.cpp: ComputeLightedTexture and the lighting
// functions it calls), rewritten for snell's scene model: ambient/emission, diffuse with brilliance, phong,
// specular, metallic highlights, reflection (min/max, fresnel, falloff, exponent, metallic), refraction
// with total internal reflection, filter/transmit and filtered shadows, termination by max_trace_level
// and adc_bailout. Single-layer textures; area lights, normals, media and photons come later.
#include "snell/render/integrator.hpp"
#include "snell/render/interior_stack.hpp"

namespace snell::render {

class WhittedIntegrator final : public Integrator {
 public:
  WhittedIntegrator(const scene::Scene& scene, const accel::Accelerator& accelerator);

  math::Color trace_camera_ray(const math::Ray& ray, TraceContext& context) const override;
  std::string_view name() const override { return "whitted"; }

  /// Colour seen along `ray` (unit direction) at recursion `level` (camera rays are level 1), with the
  /// ray's contribution `weight` to the pixel: black past max_trace_level or below adc_bailout.
  math::Color trace(const math::Ray& ray, scene::RayKind kind, int level, double weight,
                    const InteriorStack& inside, TraceContext& context) const;

 private:
  struct ShadingPoint;
  math::Color shade(const math::Ray& ray, const scene::SurfaceHit& hit, int level, double weight,
                    const InteriorStack& inside, TraceContext& context) const;
  math::Color direct_light(const ShadingPoint& sp, TraceContext& context) const;
  /// Light reaching `point` from direction `dir` within `distance`, tinted by transparent blockers.
  math::Color shadow_filter(const math::Vec3& point, const math::Vec3& normal, const math::Vec3& dir,
                            double distance, math::Color light, TraceContext& context) const;
  math::Color reflect(const ShadingPoint& sp, int level, double weight, const InteriorStack& inside,
                      TraceContext& context) const;

  const scene::Scene& scene_;
  const accel::Accelerator& accel_;
};

/// Origin for a ray leaving surface point `p` towards the side `side` points to: moved off the surface by
/// an epsilon that scales with the magnitude of p, since the hit point's floating-point error does.
math::Vec3 offset_origin(const math::Vec3& p, const math::Vec3& side);

}  // namespace snell::render
