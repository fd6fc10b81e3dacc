#pragma once
#include <memory>

#include "snell/material/finish.hpp"
#include "snell/material/pigment.hpp"
#include "snell/math/transform.hpp"

namespace snell::material {

/// POV-Ray `texture { pigment normal finish }`. `transform` maps texture space to WORLD space: it holds the
/// texture's own transforms plus every transform applied to the object after the texture was attached, so
/// a pattern moves with its object exactly as in POV-Ray (which evaluates textures at the world point).
struct Texture {
  std::shared_ptr<const Pigment> pigment;
  Finish finish;
  math::Transform transform;
  /// The layer under this one (POV-Ray 3.7 reference, "Layered Textures": `texture {A} texture {B}` puts
  /// B on top of A; where B's pigment is transparent, A shows through). Null for a single texture.
  std::shared_ptr<const Texture> below;

  /// This texture with `t` applied after its transforms, on every layer.
  std::shared_ptr<const Texture> transformed(const math::Transform& t) const;
  /// `top` placed over `bottom` (each may already be layered): a copy of top's chain ending on bottom.
  static std::shared_ptr<const Texture> layered(const std::shared_ptr<const Texture>& top,
                                                std::shared_ptr<const Texture> bottom);
  /// The pigment of the whole stack at a world point: each layer's colour over the ones below by its
  /// filter and transmit.
  Rgbft pigment_at(const math::Vec3& world_point, const math::Vec3& world_normal, const math::Vec2& uv) const;

  /// POV-Ray's default texture: black pigment, default finish.
  static std::shared_ptr<const Texture> default_texture();
};

}  // namespace snell::material
