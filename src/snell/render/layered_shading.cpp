// Layered textures lit layer by layer, as POV-Ray does (trace.cpp, ComputeLightedTexture): every layer
// has its own pigment, normal and finish; a layer's ambient, diffuse and highlights are seen through the
// layers above it (their transmitted colour, POV-Ray's filCol), while its reflection adds in full, with
// the weight left for it. `texture { T_Layered finish {..} }` changes only the top layer's finish, so the
// layers below keep theirs (advanced/chess2.pov's T_Wood20 frame).
#include <algorithm>
#include <cmath>

#include "snell/render/whitted.hpp"
#include "snell/render/whitted_shading_point.hpp"

namespace snell::render {

math::Color WhittedIntegrator::lower_layers(const ShadingPoint& top, const math::Vec3& shape_normal,
                                            const scene::Object* object, double relative_ior, int level,
                                            double weight, const InteriorStack& inside, TraceContext& context,
                                            math::Color& filter) const {
  const scene::SurfaceHit& hit = *top.hit;
  math::Color result(0);
  for (const material::Texture* layer = top.texture->below.get(); layer; layer = layer->below.get()) {
    const double trans = std::min(1.0, std::fabs(filter.grey()));
    if (trans <= scene_.settings.adc_bailout) break;
    ShadingPoint sp = top;
    sp.finish = &layer->finish_at(hit.texture_point, hit.normal, top.ray->direction);
    sp.normal = layer->own_shading_normal(hit.texture_point, shape_normal, hit.uv);
    sp.pigment = layer->own_pigment_at(hit.texture_point, hit.normal, hit.uv, top.ray->direction);
    sp.opacity = opacity_of(sp.pigment, scene_.settings.language_version);
    const double layer_weight = weight * trans;
    double reflect_weight = layer_weight;
    const math::Color reflectivity = reflectivity_of(sp, relative_ior, reflect_weight);
    result += filter * own_light(sp, object, relative_ior, level, layer_weight, inside, context);
    if (!reflectivity.is_black()) {
      const math::Color seen = reflect(sp, level, reflect_weight, inside, context);
      const double e = sp.finish->reflection_exponent;
      result += reflectivity *
                (e != 1 ? math::Color(std::pow(std::max(0.0, seen.r), e), std::pow(std::max(0.0, seen.g), e),
                                      std::pow(std::max(0.0, seen.b), e))
                        : seen);
    }
    filter *= transmitted_color(sp.pigment);
    if (sp.finish->conserve_energy && sp.finish->reflects()) {
      const math::Color keep = math::Color(1) - reflectivity;
      filter *= math::Color(std::min(1.0, keep.r), std::min(1.0, keep.g), std::min(1.0, keep.b));
    }
  }
  return result;
}

}  // namespace snell::render
