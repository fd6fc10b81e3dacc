#pragma once
// `--integrator path`: a path tracer that renders POV-Ray scenes physically, as ground truth. Finishes map
// to BSDFs (diffuse -> Lambert with albedo pigment * diffuse, phong/specular -> a normalised Phong lobe,
// reflection -> mirror, filter/transmit with interior ior -> Fresnel dielectric); emission and
// ambient-only surfaces emit. Light sources are sampled at every diffuse or glossy vertex (next-event
// estimation; area lights at a random point of their rectangle), emissive spheres are sampled by the cone
// they subtend and combined with BSDF sampling by multiple importance sampling (sphere_emitters.hpp), paths
// end by Russian roulette.
// Light units follow POV-Ray: a white light at normal incidence on a white diffuse-1 surface gives 1.
#include <vector>

#include "snell/render/integrator.hpp"
#include "snell/render/sphere_emitters.hpp"

namespace snell::render {

class PathIntegrator final : public Integrator {
 public:
  PathIntegrator(const scene::Scene& scene, const accel::Accelerator& accelerator);
  math::Color trace_camera_ray(const math::Ray& ray, TraceContext& context,
                               double max_distance = math::kInfinity) const override;
  std::string_view name() const override { return "path"; }

 private:
  /// A vertex's diffuse and glossy lobes and the probabilities with which one of them is sampled.
  struct Lobes {
    math::Color albedo;
    math::Color glossy;
    double exponent = 1;
    double p_diffuse = 0;
    double p_glossy = 0;
  };
  /// Radiance a surface emits toward any direction (emission, or ambient for objects without lobes).
  math::Color emitted(const material::Finish& f, const material::Rgbft& pigment) const;
  /// Solid-angle density with which `sample_emitters` picks a direction toward `object` from `from`.
  double emitter_pdf(const scene::Object* object, const math::Vec3& from) const;
  /// Light from one emissive sphere, sampled by its cone and weighted against the lobes' own sampling.
  math::Color sample_emitters(const math::Vec3& point, const math::Vec3& n, const math::Vec3& wo,
                              const Lobes& lobes, double time, TraceContext& context) const;
  /// Light from the scene's light sources reaching `point` (normal `n`) from direction `to_light`, times
  /// the cosine, for each light sampled once.
  math::Color sample_lights(const math::Vec3& point, const math::Vec3& n, const math::Vec3& wo,
                            const math::Color& albedo, const math::Color& glossy, double exponent,
                            TraceContext& context) const;
  bool occluded(const math::Vec3& point, const math::Vec3& n, const math::Vec3& dir, double distance) const;

  const scene::Scene& scene_;
  const accel::Accelerator& accel_;
  std::vector<SphereEmitter> emitters_;
};

}  // namespace snell::render
