#include "snell/render/glossy.hpp"

#include <algorithm>
#include <cmath>

#include "snell/render/microfacet.hpp"
#include "snell/render/optics.hpp"

namespace snell::render {

using math::Color;
using math::Vec3;

namespace {

constexpr int kDefaultSamples = 8;

/// A perturbed normal can send a reflected ray into the geometric surface; fold it back as the mirror
/// reflection does (whitted.cpp, reflect; after POV-Ray's "Reflection bugfix").
Vec3 fold_above(const Vec3& r, const Vec3& raw_normal) {
  const double n = dot(r, raw_normal);
  return n < 0 ? normalize(r - 2 * n * raw_normal) : r;
}

/// Mean of `samples` draws of `one(u1, u2)`, u1 stratified over the samples (it sets the distance from the
/// centre of the visible-normal disc, the dimension that matters most for the blur's radius).
template <typename OneSample>
void for_each_stratified(int samples, math::Pcg32& rng, const OneSample& one) {
  for (int i = 0; i < samples; ++i) {
    const double u1 = (i + rng.next_double()) / samples;
    const double u2 = rng.next_double();
    one(u1, u2);
  }
}

/// The reflection of local view `v` about microfacet normal `m`, weighted by G2(v, l) / G1(v) (0 below the
/// surface).
RoughSample reflect_off_microfacet(const RoughSurface& s, const NormalFrame& frame, const Vec3& v,
                                   const Vec3& m) {
  const Vec3 l = math::reflect(-v, m);
  if (l.z <= 0) return {frame.to_world(l), 0, true};
  const double weight = ggx_masking_shadowing(v, l, s.alpha) / ggx_masking(v, s.alpha);
  return {fold_above(normalize(frame.to_world(l)), s.raw_normal), weight, true};
}

}  // namespace

int rough_sample_count(int requested, int level) {
  if (level > 1) return 1;
  return requested > 0 ? requested : kDefaultSamples;
}

RoughSample sample_glossy_reflection(const RoughSurface& s, double u1, double u2) {
  const NormalFrame frame(s.normal);
  const Vec3 v = frame.to_local(-s.incident);
  // A mirror, or a view from behind the shading normal: the mirror direction, computed in world space so
  // that alpha 0 is exactly the smooth surface.
  if (s.alpha <= 0 || v.z <= 0)
    return {fold_above(math::reflect(s.incident, s.normal), s.raw_normal), 1, true};
  return reflect_off_microfacet(s, frame, v, sample_ggx_visible_normal(v, s.alpha, u1, u2));
}

RoughSample sample_rough_transmission(const RoughSurface& s, double eta, double u1, double u2) {
  if (s.alpha <= 0) {
    if (auto t = refract(s.incident, s.normal, eta)) return {normalize(*t), 1, false};
    return {fold_above(math::reflect(s.incident, s.normal), s.raw_normal), 1, true};
  }
  const NormalFrame frame(s.normal);
  const Vec3 v = frame.to_local(-s.incident);
  if (v.z <= 0) return {s.incident, 0, false};
  const Vec3 m = sample_ggx_visible_normal(v, s.alpha, u1, u2);
  const auto t = refract(-v, m, eta);
  if (!t) {
    // Past the critical angle of this microfacet: reflected whole, as a smooth surface would be.
    return reflect_off_microfacet(s, frame, v, m);
  }
  const Vec3 tl = normalize(*t);
  const Vec3 world = normalize(frame.to_world(tl));
  if (tl.z >= 0 || dot(world, s.raw_normal) >= 0) return {world, 0, false};
  // Fresnel transmittance of the microfacet against that of the macro surface (optics.cpp, de Greve 2006).
  const double macro = 1 - fresnel_dielectric(v.z, eta, 1.0);
  const double micro = 1 - fresnel_dielectric(dot(v, m), eta, 1.0);
  const double fresnel_ratio = macro > 1e-9 ? std::min(1.0, micro / macro) : micro;
  return {world, ggx_masking(tl, s.alpha) * fresnel_ratio, false};
}

Color glossy_reflection(const RoughSurface& surface, int samples, math::Pcg32& rng,
                        const DirectionTracer& trace) {
  Color sum;
  for_each_stratified(samples, rng, [&](double u1, double u2) {
    const RoughSample r = sample_glossy_reflection(surface, u1, u2);
    if (r.weight > 0) sum += r.weight * trace(r.direction);
  });
  return sum / static_cast<double>(samples);
}

RoughTransmission rough_transmission(const RoughSurface& surface, double eta, int samples, math::Pcg32& rng,
                                     const DirectionTracer& trace_refracted,
                                     const DirectionTracer& trace_reflected) {
  RoughTransmission sum;
  for_each_stratified(samples, rng, [&](double u1, double u2) {
    const RoughSample r = sample_rough_transmission(surface, eta, u1, u2);
    if (r.weight <= 0) return;
    if (r.reflected)
      sum.reflected += r.weight * trace_reflected(r.direction);
    else
      sum.refracted += r.weight * trace_refracted(r.direction);
  });
  const double n = samples;
  return {sum.refracted / n, sum.reflected / n};
}

}  // namespace snell::render
