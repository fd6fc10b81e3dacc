#pragma once
// Multiple subsurface scattering by Jensen's dipole, integrated over the surface around a shading point
// with importance-sampled probe rays: radii are drawn from the dipole's own fall-off, each radius is
// projected onto the object along the normal, and the irradiance found there is weighted by Rd(r).
// Source: Jensen et al. 2001 eq. 5-6 (Lo = 1/pi Rd(r) E dA); sampling by radius as in pbrt-v3's
// SeparableBSSRDF::Sample_Sp (probe rays along the normal), written anew.
#include <functional>

#include "snell/accel/accelerator.hpp"
#include "snell/material/dipole.hpp"
#include "snell/material/finish.hpp"
#include "snell/math/color.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/math/vec3.hpp"

namespace snell::render {

/// Irradiance (POV-Ray convention: light colour times cosine, no 1/pi) arriving at a surface point.
using IrradianceAt = std::function<math::Color(const math::Vec3& point, const math::Vec3& normal)>;

struct SubsurfaceQuery {
  const scene::Object* solid = nullptr;  ///< probes count only hits on this solid
  math::Vec3 point;
  math::Vec3 normal;  ///< outward unit normal at `point`
  material::Dipole dipole;
  double mm_per_unit = 10;
  int samples = 50;
};

/// The dipole of a subsurface finish: its measured material, or POV-Ray's translucency mapping with total
/// reflectance pigment * diffuse and the object's relative ior `eta`.
material::Dipole finish_dipole(const material::Finish& finish, const math::Color& pigment, double eta);

/// Diffusely re-emitted light at the query point, as a reflectance-weighted irradiance: for a flat
/// uniformly lit slab it converges to Rd_total * E.
math::Color subsurface_radiance(const SubsurfaceQuery& query, const accel::Accelerator& accelerator,
                                math::Pcg32& rng, const IrradianceAt& irradiance);

}  // namespace snell::render
