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

  /// POV-Ray's default texture: black pigment, default finish.
  static std::shared_ptr<const Texture> default_texture();
};

}  // namespace snell::material
