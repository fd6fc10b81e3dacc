#pragma once
// The GGX (Trowbridge-Reitz) microfacet distribution for glossy reflection and rough transmission, in a
// local frame whose z axis is the surface normal. Formulas: Walter, Marschner, Li, Torrance, "Microfacet
// Models for Refraction through Rough Surfaces", EGSR 2007 (D, Smith G1, refraction through a microfacet);
// Heitz, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 2014 (Lambda,
// height-correlated G2, the distribution of visible normals); Heitz, "Sampling the GGX Distribution of
// Visible Normals", JCGT 2018 (the sampling routine). `alpha` is GGX's width parameter: 0 is a mirror.
#include "snell/math/vec3.hpp"

namespace snell::render {

/// Normal distribution D(m) of unit microfacet normal `m` (0 below the surface); integrates to 1 when
/// weighted by cos(theta_m) over the hemisphere.
double ggx_distribution(const math::Vec3& m, double alpha);

/// Smith's Lambda for direction `v` (unit; only |v.z| matters, the side is the caller's business).
double ggx_lambda(const math::Vec3& v, double alpha);

/// Smith masking G1(v) = 1 / (1 + Lambda(v)).
double ggx_masking(const math::Vec3& v, double alpha);

/// Height-correlated masking-shadowing G2(v, l) = 1 / (1 + Lambda(v) + Lambda(l)) (Heitz 2014, eq. 99).
double ggx_masking_shadowing(const math::Vec3& v, const math::Vec3& l, double alpha);

/// Density of visible normals D_v(m) = G1(v) max(0, v.m) D(m) / v.z for viewer direction `v` (v.z > 0).
double ggx_visible_normal_pdf(const math::Vec3& v, const math::Vec3& m, double alpha);

/// A microfacet normal drawn from D_v for viewer `v` (v.z > 0) with two uniform numbers in [0, 1).
/// With alpha = 0 it is exactly (0, 0, 1).
math::Vec3 sample_ggx_visible_normal(const math::Vec3& v, double alpha, double u1, double u2);

/// Solid-angle density of the reflected direction l = reflect(-v, m) when m is drawn from D_v:
/// D_v(m) / (4 v.m) (Heitz 2018, eq. 17).
double ggx_reflection_pdf(const math::Vec3& v, const math::Vec3& l, double alpha);

/// A frame whose z axis is a unit normal, for moving directions into and out of the microfacet space.
struct NormalFrame {
  math::Vec3 tangent, bitangent, normal;
  explicit NormalFrame(const math::Vec3& n) : normal(n) { math::orthonormal_basis(n, tangent, bitangent); }
  math::Vec3 to_local(const math::Vec3& w) const {
    return {dot(w, tangent), dot(w, bitangent), dot(w, normal)};
  }
  math::Vec3 to_world(const math::Vec3& w) const { return w.x * tangent + w.y * bitangent + w.z * normal; }
};

}  // namespace snell::render
