#pragma once
// What the Whitted integrator knows about the surface point it shades; shared by whitted.cpp and
// layered_shading.cpp (one per layer of a layered texture).
#include "snell/material/finish.hpp"
#include "snell/material/rgbft.hpp"
#include "snell/material/texture.hpp"
#include "snell/math/ray.hpp"
#include "snell/render/whitted.hpp"
#include "snell/scene/object.hpp"

namespace snell::render {

struct WhittedIntegrator::ShadingPoint {
  const math::Ray* ray;
  const scene::SurfaceHit* hit;
  /// The texture lit here: the hit object's, or one entry of its averaged texture.
  const material::Texture* texture;
  const material::Finish* finish;
  math::Vec3 point;
  /// Geometric and shading normals, both turned to face the incoming ray.
  math::Vec3 raw_normal;
  math::Vec3 normal;
  material::Rgbft pigment;
  /// How much of the surface's own colour shows (POV-Ray's "att": less when transparent).
  double opacity = 1;
  TraceObserver* observer = nullptr;
  /// Phong and specular highlights; off for radiosity's gather rays (trace.cpp, ComputeOneLightRay: "too
  /// bright" otherwise).
  bool highlights = true;
  /// The frame of TraceContext::lit_lights holding this point's shadow-tested lights; -1 for none.
  int lit_frame = -1;
};

/// The transmitted colour of a surface colour: filter passes light tinted, transmit untinted.
inline math::Color transmitted_color(const material::Rgbft& c) {
  return c.rgb * c.filter + math::Color(c.transmit);
}

/// How much of a surface colour shows itself (POV-Ray's "att"): 3.7 scales filter by the brightest
/// channel (a black filter blocks); older versions do not (TransColour::Opacity / LegacyOpacity).
inline double opacity_of(const material::Rgbft& c, double language_version) {
  return language_version < 3.7 ? 1.0 - c.filter - c.transmit : 1.0 - c.filter * c.rgb.max() - c.transmit;
}

}  // namespace snell::render
