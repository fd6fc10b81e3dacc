#pragma once
// Participating media along a ray segment (POV-Ray 3.7 media.cpp, MediaFunction::ComputeMedia): the segment
// is split into "lit" intervals where spotlight and cylinder beams cross it, those into sampling intervals
// (`intervals`, shared out by `ratio`), and each interval is sampled by `method`: 3 is adaptive (samples at
// sub-interval ends, halved again up to aa_level where neighbours differ by more than aa_threshold), 1 and 2
// take random or jittered evenly spaced samples. A sample gathers emission and single scattering of every
// light that reaches it (shadowed, through the phase function) and the extinction, which thins everything
// behind it.
#include <functional>
#include <vector>

#include "snell/material/media.hpp"
#include "snell/math/color.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/math/ray.hpp"
#include "snell/scene/light.hpp"

namespace snell::render {

/// The light from `light` that reaches `point` (after its cone, fade and shadows) and the unit direction
/// towards the light; black when none does.
struct LightAtPoint {
  math::Color color;
  math::Vec3 direction;
};
using LightSampler = std::function<LightAtPoint(const scene::Light& light, const math::Vec3& point)>;

/// What a stretch of ray through media does to the light behind it: seen' = seen * transmittance + emitted.
struct MediaEffect {
  math::Color transmittance{1};
  math::Color emitted{0};
  math::Color apply(const math::Color& seen) const { return seen * transmittance + emitted; }
};

/// Media along `ray` (unit direction) from its origin to `depth` (finite), lit by `lights`.
MediaEffect media_along(const std::vector<const material::Media*>& media,
                        const std::vector<scene::Light>& lights, const math::Ray& ray, double depth,
                        math::Pcg32& rng, const LightSampler& light_at);

/// The extinction alone, for a shadow ray of length `depth` (POV-Ray's media_attenuation).
math::Color media_transmittance(const std::vector<const material::Media*>& media, const math::Ray& ray,
                                double depth);

/// Where along `ray` (unit direction) a spotlight or cylinder light's beam is: [t0, t1]; false when the ray
/// misses it. Point lights light everything: [0, infinity).
bool light_interval(const scene::Light& light, const math::Ray& ray, double& t0, double& t1);

}  // namespace snell::render
