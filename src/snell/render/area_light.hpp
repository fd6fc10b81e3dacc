#pragma once
// Area lights as POV-Ray 3.7 samples them (POV-Ray 3.7 reference, "Area Lights"; trace.cpp,
// TraceAreaLightShadowRay and TraceAreaLightSubsetShadowRay): an n1 x n2 grid of point lights spread over
// axis1 x axis2 around the light's centre. Shadows are the mean over the grid, found by adaptive
// subdivision: the four corners of a region are tested, and the region is split in four while the recursion
// is shallower than `adaptive` or the corners' colours differ by more than 0.1. Grid points are tested once
// each and, with `jitter`, moved by up to half a cell at random.
#include <functional>
#include <utility>

#include "snell/math/color.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/math/vec3.hpp"
#include "snell/scene/light.hpp"

namespace snell::render {

/// The light's axes as seen from a point in direction `to_light` (unit): unchanged, or with `orient`
/// turned square to that direction, both as long as axis1.
std::pair<math::Vec3, math::Vec3> area_light_axes(const scene::Light& light, const math::Vec3& to_light);

/// Offset from the light's centre of grid point (u, v), where u and v may be jittered off the integers.
/// Rectangular grids span -axis/2..+axis/2; `circular` maps each square ring of the grid onto a circle.
math::Vec3 area_light_offset(const scene::Light& light, const math::Vec3& axis1, const math::Vec3& axis2,
                             double u, double v);

/// Offset of grid point (u, v) (integers), jittered by up to half a cell with `rng` when the light jitters.
math::Vec3 area_light_sample_offset(const scene::Light& light, const math::Vec3& axis1,
                                    const math::Vec3& axis2, int u, int v, math::Pcg32& rng);

/// Mean light over the grid by POV-Ray's adaptive subdivision. `shadow(offset)` returns the light that
/// reaches the shaded point from the centre moved by `offset` (black when blocked).
math::Color area_light_shadow(const scene::Light& light, const math::Vec3& axis1, const math::Vec3& axis2,
                              math::Pcg32& rng, const std::function<math::Color(const math::Vec3&)>& shadow);

}  // namespace snell::render
