#pragma once
// `normal { bump_map { png "file" [bump_size b] [use_index | use_color] ... } }` (POV-Ray 3.7 reference,
// "Bump Maps"). The heights are the pixels' grey levels (or palette indices) times bump_size, and the
// bent normal is the normal of the triangle through the pixel and its two neighbours one row below,
// as POV-Ray's imageutil.cpp bump_map() does: the bumps depend on pixel-to-pixel steps, not on how far
// the image is scaled.
#include <memory>

#include "snell/texture/image_map.hpp"
#include "snell/texture/pattern.hpp"

namespace snell::texture {

class BumpMapPattern final : public ValuePattern, public NormalSetter {
 public:
  explicit BumpMapPattern(std::shared_ptr<const ImageMapPigment> image) : image_(std::move(image)) {}
  /// The grey level at p (what a normal_map or slope_map would see).
  double value(const Vec3& p) const override;
  /// The triangle normal laid into a frame around n whose first axis is n x y; unchanged off a `once`
  /// image.
  Vec3 set_normal(const Vec3& p, const Vec3& n, double bump_size) const override;

 private:
  double grey(double u, double v) const;

  std::shared_ptr<const ImageMapPigment> image_;
};

}  // namespace snell::texture
