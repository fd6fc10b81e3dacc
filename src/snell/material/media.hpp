#pragma once
// POV-Ray `media {}` (POV-Ray 3.7 reference, "Media"): a participating medium that emits, absorbs and
// scatters light, its strength scaled by density patterns. Used inside the interior of hollow objects and,
// as `atmosphere`, around everything.
#include <memory>
#include <vector>

#include "snell/material/pigment.hpp"
#include "snell/math/color.hpp"
#include "snell/math/transform.hpp"

namespace snell::material {

/// One `density {}` block: a pigment whose colour scales the medium, in its own space.
struct Density {
  std::shared_ptr<const Pigment> pigment;
  /// Density space -> world space.
  math::Transform transform;
};

struct Media {
  /// Scattering phase functions, numbered as POV-Ray's `scattering { type, colour }` (POV-Ray 3.7 reference,
  /// "Scattering": 1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein).
  enum class Phase { isotropic = 1, mie_hazy = 2, mie_murky = 3, rayleigh = 4, henyey_greenstein = 5 };
  Phase phase = Phase::isotropic;
  double eccentricity = 0;
  math::Color absorption{0}, emission{0}, scattering{0};
  /// `extinction`: how much of the scattering colour also takes light out of the ray.
  double scattering_extinction = 1;
  // Sampling (POV-Ray 3.5+ defaults: method 3, one interval, ten samples).
  int method = 3;
  int intervals = 1;
  int min_samples = 10, max_samples = 10;
  double jitter = 0;
  double aa_threshold = 0.1;
  int aa_level = 3;
  double ratio = 0.9, confidence = 0.9, variance = 1.0 / 128.0;
  /// Multiplied together; none means density 1 everywhere.
  std::vector<Density> densities;

  math::Color extinction() const { return absorption + scattering * scattering_extinction; }
  /// The product of the densities at a world point (each channel separately).
  math::Color density_at(const math::Vec3& world_point) const;
  /// This medium with `t` applied after its densities' transforms (the medium moves with its object).
  Media transformed(const math::Transform& t) const;
  /// The phase function's weight for light arriving from direction `to_light` seen along `view`, both
  /// unit (POV-Ray media.cpp, ComputeMediaScatteringAttenuation: isotropic is 1, not 1/4pi).
  double phase_weight(const math::Vec3& to_light, const math::Vec3& view) const;
};

}  // namespace snell::material
