#pragma once
// Emissive spheres as light sources for the path integrator: a sphere seen from outside subtends a cone,
// and directions drawn uniformly in that cone hit it (Shirley and Wang 1991, "Direct lighting calculation by
// Monte Carlo integration"; PBRT 3rd ed. section 14.2.2). Combined with BSDF sampling by the power heuristic
// (Veach and Guibas 1995), small bright spheres light a scene with little noise while large ones stay
// unbiased. Other emissive shapes are found only by BSDF sampling.
#include <optional>
#include <vector>

#include "snell/material/finish.hpp"
#include "snell/math/color.hpp"
#include "snell/math/vec3.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render {

struct SphereEmitter {
  const scene::Object* object = nullptr;
  math::Vec3 center;
  double radius = 0;
};

/// What a finish emits for the path integrator, before pigment and opacity: its `emission`, plus
/// ambient x ambient_light when it has no diffuse, specular or phong lobe (POV-Ray's way of making
/// visible light shapes).
math::Color finish_emission(const material::Finish& f, const math::Color& ambient_light);

/// Spheres whose finish emits at their centre (finish_emission is not black) and
/// whose transform keeps them spheres (rotation, uniform scale, translation); still objects only.
std::vector<SphereEmitter> find_sphere_emitters(const scene::Scene& scene);

/// Solid-angle density of `sample_sphere_cone` at any direction that hits the sphere from `point`;
/// 0 when the point is inside the sphere (then the cone is undefined and BSDF sampling alone finds it).
double sphere_cone_pdf(const SphereEmitter& emitter, const math::Vec3& point);

/// A unit direction from `point` uniform in the cone the sphere subtends (u1, u2 in [0,1)); nullopt from
/// inside.
std::optional<math::Vec3> sample_sphere_cone(const SphereEmitter& emitter, const math::Vec3& point, double u1,
                                             double u2);

/// Veach's power heuristic with beta 2 for one sample of each strategy.
inline double power_heuristic(double pdf_this, double pdf_other) {
  const double a = pdf_this * pdf_this;
  const double b = pdf_other * pdf_other;
  return a + b > 0 ? a / (a + b) : 0;
}

}  // namespace snell::render
