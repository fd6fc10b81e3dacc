#include "snell/texture/material_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace snell::texture {

MaterialMapSelector::MaterialMapSelector(MaterialMapImage image,
                                         std::vector<std::shared_ptr<const material::Texture>> textures)
    : image_(std::move(image)), textures_(std::move(textures)) {
  if (image_.width <= 0 || image_.height <= 0 ||
      image_.numbers.size() != static_cast<size_t>(image_.width) * image_.height)
    throw std::invalid_argument("material_map needs a non-empty image");
  if (textures_.empty()) throw std::invalid_argument("material_map needs at least one texture");
}

material::TextureSelector::Choice MaterialMapSelector::at(const material::PatternPoint& point) const {
  const ImageUv uv = image_map_uv(image_.type, point.p);
  if (image_.once && (uv.u < 0 || uv.u >= 1 || uv.v < 0 || uv.v >= 1))
    return {textures_.front().get(), nullptr, 0, point.p};
  const double u = uv.u - std::floor(uv.u), v = uv.v - std::floor(uv.v);
  // Row 0 is the top of the image, at v = 1 (as for image_map); the nearest pixel, never interpolated.
  const int x = std::clamp(static_cast<int>(u * image_.width), 0, image_.width - 1);
  const int y = std::clamp(static_cast<int>((1 - v) * image_.height), 0, image_.height - 1);
  const int number = image_.numbers[static_cast<size_t>(y) * image_.width + x];
  const int count = static_cast<int>(textures_.size());
  return {textures_[static_cast<size_t>(((number % count) + count) % count)].get(), nullptr, 0, point.p};
}

}  // namespace snell::texture
