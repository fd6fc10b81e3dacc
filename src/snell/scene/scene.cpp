#include "snell/scene/scene.hpp"

namespace snell::scene {

double Scene::effective_assumed_gamma() const {
  if (settings.assumed_gamma > 0) return settings.assumed_gamma;
  // POV-Ray 3.7: a 3.7 scene without assumed_gamma defaults to 1.0; older scenes get no gamma handling,
  // i.e. colours pass to the file as written, which is assumed_gamma equal to the output gamma.
  return settings.language_version >= 3.7 ? 1.0 : 2.2;
}

}  // namespace snell::scene
