// `texture { average texture_map {..} }` lit as POV-Ray lights it (trace.cpp, ComputeAverageTextureColours):
// every entry is shaded on its own, with its own pigment, normal, finish, layers, reflection and
// refraction, and the colours are averaged with the entries' weights. Blending the entries' pigments under
// one finish (the stand-in in Texture's own fields) is not the same once their finishes differ.
#include "snell/render/whitted.hpp"

namespace snell::render {

math::Color WhittedIntegrator::shade_averaged(const math::Ray& ray, const scene::SurfaceHit& hit,
                                              const material::Texture& texture, int level, double weight,
                                              const InteriorStack& inside, TraceContext& context) const {
  math::Color sum(0);
  double total = 0;
  for (const auto& [entry_weight, entry] : texture.averaged) {
    sum += shade(ray, hit, level, weight, inside, context, entry.get()) * entry_weight;
    total += entry_weight;
  }
  // The parser refuses weights that sum to zero (average_texture.hpp).
  return sum / total;
}

}  // namespace snell::render
