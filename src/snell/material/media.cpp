#include "snell/material/media.hpp"

#include <cmath>

namespace snell::material {

math::Color Media::density_at(const math::Vec3& world_point) const {
  math::Color d(1);
  for (const Density& density : densities) {
    const math::Vec3 p = density.transform.inverse_point(world_point);
    d *= density.pigment->at(PatternPoint{p, math::Vec3{0, 0, 0}, math::Vec2{}}).rgb;
    if (d.is_black()) break;  // the product stays 0: the densities after this one need no evaluation
  }
  return d;
}

Media Media::transformed(const math::Transform& t) const {
  Media m = *this;
  for (Density& density : m.densities) density.transform = t * density.transform;
  return m;
}

double Media::phase_weight(const math::Vec3& to_light, const math::Vec3& view) const {
  // The constants are POV-Ray's (media.cpp), so scenes keep their brightness.
  const double alpha = dot(to_light, view);
  switch (phase) {
    case Phase::rayleigh:
      return 0.799372013 * (1.0 + alpha * alpha);
    case Phase::mie_hazy:
      return 0.576655375 * (1.0 + 9.0 * std::pow(0.5 * (1.0 + alpha), 8.0));
    case Phase::mie_murky:
      return 0.495714547 * (1.0 + 50.0 * std::pow(0.5 * (1.0 + alpha), 32.0));
    case Phase::henyey_greenstein: {
      const double g = eccentricity;
      return (1.0 - g * g) / std::pow(1.0 + g * g - 2.0 * g * alpha, 1.5);
    }
    case Phase::isotropic:
      break;
  }
  return 1.0;
}

}  // namespace snell::material
