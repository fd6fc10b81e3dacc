#pragma once
// `image_pattern { png "file" ... }` and the heights of `bump_map` (POV-Ray 3.7 reference, "Image
// Pattern", "Bump Maps"): an image map read as a value pattern, the value being the pixel's grey level.
#include <memory>

#include "snell/texture/image_map.hpp"
#include "snell/texture/pattern.hpp"

namespace snell::texture {

class ImagePattern final : public ValuePattern {
 public:
  explicit ImagePattern(std::shared_ptr<const ImageMapPigment> image) : image_(std::move(image)) {}
  /// Luminance with Rec. 709 weights (0.2126, 0.7152, 0.0722), in [0,1] for an image in [0,1].
  double value(const Vec3& p) const override;

 private:
  std::shared_ptr<const ImageMapPigment> image_;
};

}  // namespace snell::texture
