#pragma once
// The ray from a surface point towards a light and the light's colour arriving there before shadows:
// distance fade and spotlight/cylinder cones (POV-Ray 3.7 reference, "Light Source": fade_distance,
// fade_power, spotlight radius/falloff/tightness, cylinder, parallel).
#include "snell/math/color.hpp"
#include "snell/math/vec3.hpp"
#include "snell/scene/light.hpp"

namespace snell::render {

struct LightRay {
  /// Unit direction from the point towards the light.
  math::Vec3 direction;
  /// Distance along `direction` within which objects cast shadows.
  double distance = 0;
  /// Light colour after fade and cone attenuation (black outside a cone).
  math::Color color;
};

/// The ray from `point` towards the light with its colour after fade and cone attenuation.
LightRay light_ray(const scene::Light& light, const math::Vec3& point);

/// Direction and shadow distance from `point` towards the light's centre moved by `offset` (an area light's
/// sample point); `color` is left black. Cylinder and parallel lights send parallel rays along the line from
/// point_at to the moved centre (POV-Ray 3.7 trace.cpp, ComputeOneWhiteLightRay).
LightRay light_direction(const scene::Light& light, const math::Vec3& point, const math::Vec3& offset = {});

/// Fade and cone attenuation of the light reaching `point` along `toward` (from light_direction).
double light_attenuation(const scene::Light& light, const math::Vec3& point, const LightRay& toward);

/// POV-Ray's smooth step between `low` and `high` for spotlight edges: 0 below, 1 above, 3t^2-2t^3 between.
double cone_spline(double low, double high, double x);

}  // namespace snell::render
