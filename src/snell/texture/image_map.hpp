#pragma once
// `pigment { image_map { png "file" map_type n interpolate n once filter all f transmit all t } }`
// (POV-Ray 3.7 reference, "Image Maps"): an image laid on the unit square of the x-y plane (map_type 0,
// repeated in x and y unless `once`), around the origin like a globe (1) or a can along y (2).
#include <memory>

#include "snell/io/image.hpp"
#include "snell/material/pigment.hpp"

namespace snell::texture {

enum class ImageMapType { planar = 0, spherical = 1, cylindrical = 2 };

/// Image coordinates of a point: u to the right, v up, the image covering [0,1) in each (repeating
/// outside for the planar and cylindrical maps).
struct ImageUv {
  double u;
  double v;
};
ImageUv image_map_uv(ImageMapType type, const math::Vec3& p);

struct ImageMapSpec {
  /// Linear RGB (the parser decodes the file's gamma).
  std::shared_ptr<const io::Image> image;
  ImageMapType type = ImageMapType::planar;
  /// 0: nearest pixel; 2 (bilinear) and 4 (normalised distance) both interpolate bilinearly here.
  int interpolate = 0;
  /// Outside the unit square the map is clear (transmit 1) instead of repeating.
  bool once = false;
  double filter_all = 0;
  double transmit_all = 0;
};

class ImageMapPigment final : public material::Pigment {
 public:
  /// Throws std::invalid_argument for an empty image.
  explicit ImageMapPigment(ImageMapSpec spec);
  material::Rgbft at(const material::PatternPoint& point) const override;
  const ImageMapSpec& spec() const { return spec_; }
  /// The colour at image coordinates (u, v) in [0,1), with the spec's interpolation.
  math::Color texel(double u, double v) const;

 private:
  ImageMapSpec spec_;
};

}  // namespace snell::texture
