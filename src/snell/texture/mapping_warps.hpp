#pragma once
// POV-Ray's warps other than turbulence (POV-Ray 3.7 reference, "Warps"): black_hole pulls the pattern
// toward (or, inverted, pushes it from) a centre; repeat tiles a slab of the pattern along one axis with
// optional offset and mirror flips; cylindrical, spherical, toroidal and planar wrap the pattern's x-y
// plane around a shape, reading the point as (angle, height, distance). The formulas follow the
// reference's description and POV-Ray's warp.cpp behaviour (the point maps to (theta/2pi, y, r), etc.).
#include "snell/texture/warp.hpp"

namespace snell::texture {

struct BlackHoleParams {
  Vec3 center{0, 0, 0};
  double radius = 1;
  double strength = 1;
  /// `falloff`: the power of the distance-from-the-edge fraction.
  double falloff = 2;
  bool inverse = false;
  /// `repeat <v>`: a black hole in every cell of this size (0 components: no repeat on that axis).
  Vec3 repeat{0, 0, 0};
  /// `turbulence <v>`: each repeated hole's centre moved by up to this much, fixed per cell.
  Vec3 jitter{0, 0, 0};
};

class BlackHoleWarp final : public Warp {
 public:
  explicit BlackHoleWarp(const BlackHoleParams& params) : params_(params) {}
  Vec3 warp(const Vec3& p) const override;

 private:
  BlackHoleParams params_;
};

/// `repeat <width along one axis> offset <v> flip <v>`: block k along the axis shows the pattern of
/// block 0, moved by k * offset; odd blocks are mirrored on the flipped axes.
class RepeatWarp final : public Warp {
 public:
  /// `axis` 0..2; `flip` holds -1 on mirrored axes and 1 elsewhere.
  RepeatWarp(int axis, double width, const Vec3& offset, const Vec3& flip)
      : axis_(axis), width_(width), offset_(offset), flip_(flip) {}
  Vec3 warp(const Vec3& p) const override;

 private:
  int axis_;
  double width_;
  Vec3 offset_;
  Vec3 flip_;
};

/// The wrapping warps: cylindrical, spherical, toroidal and planar.
class MappingWarp final : public Warp {
 public:
  enum class Kind { cylindrical, spherical, toroidal, planar };
  struct Params {
    Kind kind = Kind::cylindrical;
    /// Unit vector the wrapped pattern's z axis lies along (POV-Ray's default: +z).
    Vec3 orientation{0, 0, 1};
    /// `dist_exp`: the angles are scaled by distance^dist_exp (0: not at all).
    double dist_exp = 0;
    double major_radius = 1;  // toroidal
    double offset = 0;        // planar: the z the plane's points get
  };
  explicit MappingWarp(const Params& params) : params_(params) {}
  Vec3 warp(const Vec3& p) const override;

 private:
  Params params_;
};

}  // namespace snell::texture
