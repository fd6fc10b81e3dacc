#pragma once
// POV-Ray 3.7's own estimate of subsurface light for `finish { subsurface { translucency T } }`, so that its
// scenes render as POV-Ray renders them (conformance scene subsurface, issue 7). Behaviour read from
// POV-Ray 3.7 source/core/render/trace.cpp (ComputeSubsurfaceScattering and the functions it calls) and
// source/core/lighting/subsurface.*; the code here is written anew. It differs from snell's importance-
// sampled dipole (subsurface.hpp) in ways that show in images:
// - the surface around the point is found by rays in uniformly random directions from a point one mean
//   free path below the surface, each weighted by the area it stands for (4 pi d^2 / cos), and the sum is
//   divided by the number of rays that hit something: on an open surface (a plane) half the rays find
//   nothing, so that surface returns about twice the dipole's total reflectance;
// - the dipole is weighted by the Fresnel transmittance where the light enters and where it leaves;
// - POV-Ray's own diffuse Fresnel reflectance approximation sets the dipole's boundary term and the map
//   from pigment * diffuse to the reduced albedo;
// - a single-scattering term (Jensen et al. 2001 eq. 3 as POV-Ray evaluates it) is added.
// The unscattered light that passes straight through thin parts is left out (it needs a full trace).
#include <functional>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/math/color.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/math/vec3.hpp"

namespace snell::render {

/// POV-Ray's diffuse Fresnel reflectance approximation (subsurface.h, FresnelDiffuseReflectance), used in
/// place of Egan and Hilgeman's fit, which fails for large eta.
double povray_diffuse_fresnel_reflectance(double eta);

/// POV-Ray's Fresnel transmittance for light meeting the surface at angle `phi` from the normal
/// (trace.cpp, ComputeFt): 1 - the unpolarised Fresnel reflectance (Cook and Torrance's form).
double povray_fresnel_transmittance(double phi, double eta);

/// The reduced albedo whose total diffuse reflectance (Jensen et al. 2001 section 2.3, with POV-Ray's
/// boundary term for `ior`) is `rd`, as POV-Ray's precomputed table maps pigment * diffuse.
double povray_reduced_albedo(double rd, double ior);

/// One light's light arriving at a surface point: unit direction towards the light and its colour after
/// shadows (not yet times the cosine).
struct IncidentLight {
  math::Vec3 direction;
  math::Color color;
};
/// Fills `out` with the lights reaching `point`; `normal` is the surface's normal there (either side).
using LightsAt =
    std::function<void(const math::Vec3& point, const math::Vec3& normal, std::vector<IncidentLight>& out)>;

struct PovraySubsurfaceQuery {
  const scene::Object* solid = nullptr;  ///< the translucent solid; hits on others count as other objects
  math::Vec3 point;
  math::Vec3 normal;         ///< unit normal at `point`, facing the viewer
  math::Vec3 to_viewer;      ///< unit direction from `point` back along the eye ray
  math::Color reflectance;   ///< pigment * diffuse
  math::Color translucency;  ///< 1 / sigma_s' in mm
  double ior = 1.5;          ///< relative index of refraction, inside over outside
  double mm_per_unit = 10;
  int diffuse_samples = 50;
  int single_samples = 50;
};

/// The diffuse (dipole) and single-scattering light leaving the query point, in POV-Ray's convention
/// (no 1/pi: light intensities already carry it).
math::Color povray_subsurface_radiance(const PovraySubsurfaceQuery& query,
                                       const accel::Accelerator& accelerator, math::Pcg32& rng,
                                       const LightsAt& lights);

}  // namespace snell::render
