#include "snell/material/texture.hpp"

namespace snell::material {

std::shared_ptr<const Texture> Texture::default_texture() {
  static const auto texture = [] {
    auto t = std::make_shared<Texture>();
    t->pigment = std::make_shared<SolidPigment>(Rgbft{});
    return std::shared_ptr<const Texture>(t);
  }();
  return texture;
}

}  // namespace snell::material
