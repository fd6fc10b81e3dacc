#pragma once
#include <memory>

#include "snell/material/finish.hpp"
#include "snell/material/pigment.hpp"
#include "snell/math/transform.hpp"

namespace snell::material {

/// POV-Ray `texture { pigment normal finish }`. `transform` maps texture space to object space: it holds
/// the texture's own transforms plus those applied to the object after the texture was attached.
struct Texture {
  std::shared_ptr<const Pigment> pigment;
  Finish finish;
  math::Transform transform;

  /// POV-Ray's default texture: black pigment, default finish.
  static std::shared_ptr<const Texture> default_texture();
};

}  // namespace snell::material
