#pragma once
#include <memory>
#include <vector>

#include "snell/math/color.hpp"
#include "snell/math/vec3.hpp"
#include "snell/scene/object.hpp"
#include "snell/scene/photon_settings.hpp"

namespace snell::scene {

/// POV-Ray `light_source {}`. One struct for POV-Ray's fixed set of light kinds: the integrator
/// samples it through `illumination_at` so area lights and spot cones live in one place.
struct Light {
  enum class Kind { point, spotlight, cylinder, parallel };
  Kind kind = Kind::point;
  math::Vec3 position;
  math::Color color{1};
  bool shadowless = false;
  /// Attenuation 2 / (1 + (d / fade_distance)^fade_power) when both are set (POV-Ray 3.7 "fade_distance").
  double fade_distance = 0;
  double fade_power = 0;
  // spotlight / cylinder
  math::Vec3 point_at{0, 0, 1};
  double radius = 30;   // degrees (spotlight), units (cylinder)
  double falloff = 45;  // degrees (spotlight), units (cylinder)
  double tightness = 0;
  // area_light
  bool area = false;
  math::Vec3 axis1, axis2;
  int size1 = 1, size2 = 1;
  int adaptive = 0;
  bool jitter = false, circular = false, orient = false;
  /// `area_illumination`: every grid point lights the surface from its own direction, not only shadows.
  bool area_illumination = false;
  bool media_interaction = true, media_attenuation = false;
  /// `projected_through { object }`: light reaches only the points whose ray to the light crosses one of
  /// these (the object itself is not drawn).
  std::vector<std::shared_ptr<const Object>> projected_through;
  /// `photons {}` in the light (scene/photon_settings.hpp).
  LightPhotons photons;
};

}  // namespace snell::scene
