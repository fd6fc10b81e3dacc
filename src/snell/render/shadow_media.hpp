#pragma once
// Media that a shadow ray crosses inside objects (POV-Ray 3.7 trace.cpp, ComputeShadowColour: every
// stretch of a light ray inside a solid whose interior holds media is thinned by that media's extinction,
// whatever the light's media_attenuation, so clouds shade the ground and themselves).
// The ray is followed crossing by crossing; a solid it leaves without having entered held its origin.
#include <array>
#include <cstddef>

#include "snell/math/color.hpp"
#include "snell/math/ray.hpp"
#include "snell/scene/object.hpp"

namespace snell::render {

class ShadowMedia {
 public:
  /// `ray`: the shadow ray from its true start (unit direction).
  explicit ShadowMedia(const math::Ray& ray) : ray_(ray) {}

  /// Whether `solid` holds media that a shadow ray must account for.
  static bool has_media(const scene::Object& solid);

  /// The ray crosses `solid`'s surface at distance `t`; `outward` is the solid's outward normal there.
  void cross(const scene::Object& solid, double t, const math::Vec3& outward);

  /// The fraction of light that gets through the media crossed so far, the solids still open ending
  /// at `end` (where the light is).
  math::Color transmittance(double end) const;

 private:
  struct Open {
    const scene::Object* solid;
    double t0;
  };
  /// Thins the light by `solid`'s media over [t0, t1].
  void thin(const scene::Object& solid, double t0, double t1);

  math::Ray ray_;
  std::array<Open, 8> open_{};
  size_t open_count_ = 0;
  math::Color through_{1};
};

}  // namespace snell::render
