#pragma once
// `texture { material_map { png "file" [map_type n] [once] texture {..} texture {..} ... } }` (POV-Ray 3.7
// reference, "Material Maps"): an image laid like an image_map picks, per point, one texture of the list:
// a palette image by its pixel's palette index, any other image by its red channel times 255. Indices past
// the list wrap around (modulo its length); outside a `once` image the first texture shows.
#include <memory>
#include <vector>

#include "snell/material/texture.hpp"
#include "snell/texture/image_map.hpp"

namespace snell::texture {

struct MaterialMapImage {
  int width = 0;
  int height = 0;
  /// Row-major from the top row: each pixel's texture number before wrapping.
  std::vector<int> numbers;
  ImageMapType type = ImageMapType::planar;
  bool once = false;
};

class MaterialMapSelector final : public material::TextureSelector {
 public:
  /// Throws std::invalid_argument for an empty image or no textures.
  MaterialMapSelector(MaterialMapImage image, std::vector<std::shared_ptr<const material::Texture>> textures);
  Choice at(const material::PatternPoint& point) const override;

 private:
  MaterialMapImage image_;
  std::vector<std::shared_ptr<const material::Texture>> textures_;
};

}  // namespace snell::texture
