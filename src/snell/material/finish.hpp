#pragma once
#include <optional>

#include "snell/material/dipole.hpp"
#include "snell/math/color.hpp"

namespace snell::material {

/// POV-Ray 3.7 `finish {}` with its documented defaults (POV-Ray 3.7 reference, "Finish").
struct Finish {
  math::Color ambient{0.1};
  math::Color emission{0};
  double diffuse = 0.6;
  double brilliance = 1;
  double crand = 0;
  double phong = 0;
  double phong_size = 40;
  double specular = 0;
  double roughness = 0.05;
  /// `metallic`: highlights take the surface colour (0 = white highlights, 1 = fully tinted).
  double metallic = 0;
  /// `reflection { min max fresnel falloff exponent metallic }`; a plain `reflection c` sets min = max = c.
  math::Color reflection_min{0};
  math::Color reflection_max{0};
  bool reflection_fresnel = false;
  double reflection_falloff = 1;
  /// The power the reflected colour is raised to: 1 / the scene's `exponent` (as POV-Ray stores it).
  double reflection_exponent = 1;
  double reflection_metallic = 0;
  /// snell extension `reflection { ... blur A samples N }`: GGX alpha of glossy reflection (0 = mirror) and
  /// rays per camera-ray hit (0 = the default, render/glossy.hpp).
  double reflection_blur = 0;
  int reflection_samples = 0;
  /// snell extension `transmission { blur A samples N }`: frosted refraction, the same way.
  double transmission_blur = 0;
  int transmission_samples = 0;
  bool conserve_energy = false;
  /// Whether `ambient` was given explicitly (3.7: then it overrides, else emission/ambient rules apply).
  bool ambient_set = false;

  /// `subsurface { translucency <c> }` (POV-Ray 3.7 reference, "Subsurface Light Transport"): the diffuse
  /// term becomes Jensen's dipole; translucency is the mean free path 1/sigma_s' in mm. `material "name"`
  /// (a snell extension) takes sigma_s', sigma_a and eta from Jensen et al. 2001's measured table instead.
  bool subsurface = false;
  math::Color subsurface_translucency{1};
  std::optional<Dipole> subsurface_material;

  bool reflects() const { return reflection_max.max() > 0 || reflection_min.max() > 0; }
};

}  // namespace snell::material
