#pragma once
// Glossy reflection and rough (frosted) transmission for the Whitted integrator, a snell extension:
// `finish { reflection { ... blur A samples N } }` and `finish { transmission { blur A samples N } }`
// (docs/language.md, "Glossy reflection and frosted glass"). Each surface ray becomes N rays through GGX
// microfacet normals drawn from the distribution of visible normals (microfacet.hpp), averaged with the
// masking-shadowing weight; the finish's reflection colour and the pigment's filter/transmit still set how
// much light goes each way, as in POV-Ray, so blur 0 gives exactly the mirror and Snell directions.
#include <functional>

#include "snell/math/color.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/math/vec3.hpp"

namespace snell::render {

/// The surface as the incoming ray meets it.
struct RoughSurface {
  /// Unit direction of the incoming ray (towards the surface).
  math::Vec3 incident;
  /// Shading normal and geometric normal, both turned to face the incoming ray.
  math::Vec3 normal;
  math::Vec3 raw_normal;
  /// GGX alpha (> 0).
  double alpha = 0;
};

/// Colour arriving along a unit direction leaving the surface.
using DirectionTracer = std::function<math::Color(const math::Vec3& direction)>;

/// How many rays a rough surface sends at recursion `level` (camera rays are level 1): `requested` (or 8
/// when 0) where a camera ray hits, 1 below, so that nested glossy surfaces do not multiply their rays.
int rough_sample_count(int requested, int level);

/// Mean reflected colour over `samples` GGX reflections, each weighted by G2(v, l) / G1(v) (the estimator
/// of the microfacet BRDF times cos over the visible-normal density, Heitz 2018 eq. 19).
math::Color glossy_reflection(const RoughSurface& surface, int samples, math::Pcg32& rng,
                              const DirectionTracer& trace);

/// Mean light through a rough dielectric boundary, `eta` = n1 / n2 (Walter et al. 2007): `refracted` is the
/// part that crosses (to be tinted by the surface's filter), `reflected` the part totally reflected by
/// microfacets past the critical angle.
struct RoughTransmission {
  math::Color refracted;
  math::Color reflected;
};
RoughTransmission rough_transmission(const RoughSurface& surface, double eta, int samples, math::Pcg32& rng,
                                     const DirectionTracer& trace_refracted,
                                     const DirectionTracer& trace_reflected);

/// One GGX scattering decision with its estimator weight (0 for a direction on the wrong side).
struct RoughSample {
  math::Vec3 direction;
  double weight = 0;
  /// True when the ray was reflected (always for glossy reflection; TIR for transmission).
  bool reflected = true;
};

/// The reflection through one microfacet drawn with uniform numbers (u1, u2).
RoughSample sample_glossy_reflection(const RoughSurface& surface, double u1, double u2);

/// The refraction (or total internal reflection) through one microfacet drawn with (u1, u2). The refracted
/// weight is G1(t) (masking towards the transmitted direction) times the microfacet's Fresnel transmittance
/// relative to that of the macro surface, capped at 1: the filter colour already accounts for the macro
/// surface, and the ratio is exactly 1 at alpha = 0.
RoughSample sample_rough_transmission(const RoughSurface& surface, double eta, double u1, double u2);

}  // namespace snell::render
