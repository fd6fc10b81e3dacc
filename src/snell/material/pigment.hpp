#pragma once
#include "snell/material/rgbft.hpp"
#include "snell/math/vec3.hpp"

namespace snell::material {

/// What a pigment sees of the surface point. `p` is in the texture's own space (the world point taken back
/// through Texture::transform), as POV-Ray evaluates patterns.
struct PatternPoint {
  math::Vec3 p;
  math::Vec3 world_normal;
  math::Vec2 uv;
  /// Unit direction of the ray that met the surface (the `aoi` pattern); zero where no ray is known.
  math::Vec3 ray_direction{};
};

/// The colour of a surface at a point: solid colours now, patterns with maps later (texture/).
class Pigment {
 public:
  virtual ~Pigment() = default;
  virtual Rgbft at(const PatternPoint& point) const = 0;
  /// True when `at` returns the same colour everywhere (lets the integrator skip the evaluation).
  virtual bool is_constant() const { return false; }
  /// False only when `at` can never give filter or transmit above 0: a shadow ray stopped by the surface is
  /// then black without evaluating the pigment. True when unsure.
  virtual bool may_transmit() const { return true; }
};

class SolidPigment final : public Pigment {
 public:
  explicit SolidPigment(const Rgbft& color) : color_(color) {}
  Rgbft at(const PatternPoint&) const override { return color_; }
  bool is_constant() const override { return true; }
  bool may_transmit() const override { return color_.is_transparent(); }
  const Rgbft& color() const { return color_; }

 private:
  Rgbft color_;
};

}  // namespace snell::material
