#pragma once
// Fog along a ray (POV-Ray 3.7 trace.cpp, ComputeFog, ComputeConstantFogDepth, ComputeGroundFogDepth).
#include <vector>

#include "snell/math/color.hpp"
#include "snell/math/ray.hpp"
#include "snell/scene/fog.hpp"

namespace snell::render {

/// The fraction of light that crosses `depth` units of `ray` (unit direction) through `fog`, before its
/// filter and transmit (1 for a fog without distance).
double fog_transmittance(const scene::Fog& fog, const math::Ray& ray, double depth);

/// What all fogs together do over `depth` along a ray: seen' = seen * through + added.
struct FogEffect {
  math::Color through{1};
  math::Color added{0};
};
FogEffect fogs_along(const std::vector<scene::Fog>& fogs, const math::Ray& ray, double depth);

/// `seen`, the colour at distance `depth` along the ray (infinity for the sky), as it reaches the ray's
/// origin through every fog: thinned by each and mixed with the fog colours.
math::Color apply_fogs(const std::vector<scene::Fog>& fogs, const math::Ray& ray, double depth,
                       const math::Color& seen);

}  // namespace snell::render
