#pragma once
// Dielectric optics shared by the integrators: Snell's law in vector form and the unpolarised Fresnel
// reflectance (Bram de Greve, "Reflections and Refractions in Ray Tracing", 2006).
#include <optional>

#include "snell/math/vec3.hpp"

namespace snell::render {

/// Unpolarised Fresnel reflectance for light going from a medium of index n1 into n2, with
/// `cos_i` = cosine of the angle of incidence (>= 0). Returns 1 under total internal reflection.
double fresnel_dielectric(double cos_i, double n1, double n2);

/// The s and p amplitude reflectances squared (Rs, Rp); both 1 under total internal reflection.
struct FresnelTerms {
  double rs = 1, rp = 1;
};
FresnelTerms fresnel_terms(double cos_i, double n1, double n2);

/// Schlick's approximation of `fresnel_dielectric` (uses cos of the transmitted angle when n1 > n2).
double fresnel_schlick(double cos_i, double n1, double n2);

/// Refracted direction of unit `incident` (pointing at the surface) through a surface with unit normal `n`
/// facing the incident side, `eta` = n1 / n2. nullopt under total internal reflection.
std::optional<math::Vec3> refract(const math::Vec3& incident, const math::Vec3& n, double eta);

/// Whether light at incidence cosine `cos_i` is totally reflected going from index n1 to n2.
bool total_internal_reflection(double cos_i, double n1, double n2);

}  // namespace snell::render
