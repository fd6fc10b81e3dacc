#include "snell/scene/scene.hpp"

namespace snell::scene {

double Scene::effective_assumed_gamma() const {
  if (settings.assumed_gamma > 0) return settings.assumed_gamma;
  // POV-Ray 3.7: a 3.7 scene without assumed_gamma defaults to 1.0; older scenes get no gamma handling,
  // i.e. colours pass to the file as written, which is assumed_gamma equal to the output gamma.
  return settings.language_version >= 3.7 ? 1.0 : 2.2;
}

double Scene::working_gamma() const {
  const bool gamma_handling = settings.assumed_gamma > 0 || settings.language_version >= 3.7;
  return gamma_handling ? effective_assumed_gamma() : 1.0;
}

math::Color Scene::miss_color(const math::Vec3& direction) const {
  if (!sky_sphere) return background.rgb;
  material::PatternPoint point;
  point.p = normalize(sky_sphere->transform.inverse_vector(normalize(direction)));
  math::Color result = background.rgb;
  for (const auto& pigment : sky_sphere->pigments) {
    const material::Rgbft c = pigment->at(point);
    // A layer covers what lies below except where it lets light through (filter tints, transmit does not).
    result = c.rgb * (1 - c.filter - c.transmit) + result * (c.rgb * c.filter + math::Color(c.transmit));
  }
  return result;
}

}  // namespace snell::scene
