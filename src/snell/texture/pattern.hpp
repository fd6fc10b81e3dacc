#pragma once
// POV-Ray patterns (POV-Ray 3.7 reference, "Patterns"). Two families:
// - value patterns map a point to a number in [0,1] that a colour/pigment map turns into colour;
// - block patterns (checker, hexagon, brick) pick one of a fixed list of pigments.

#include "snell/math/vec3.hpp"

namespace snell::texture {

using math::Vec3;

class ValuePattern {
 public:
  virtual ~ValuePattern() = default;
  /// The pattern's value at `p` (texture space), in [0,1] before the wave function.
  virtual double value(const Vec3& p) const = 0;
  /// The value where the surface matters too: `world_normal` (unit, outward, for `slope`) and the unit
  /// direction of the ray that met it (`aoi`; zero when unknown).
  virtual double value_at(const Vec3& p, const Vec3& world_normal, const Vec3& ray_direction) const {
    return value(p);
  }
};

/// A pattern with its own way of bending a surface normal (POV-Ray normal.cpp: bumps, dents, wrinkles,
/// ripples, waves), used by `normal { pattern bump_size }` instead of the pattern's finite-difference
/// gradient.
class BumpSource {
 public:
  virtual ~BumpSource() = default;
  /// The vector added to the unit normal (in pattern space) per unit of bump_size.
  virtual Vec3 bump(const Vec3& p) const = 0;
};

/// A pattern that sets the bent normal itself instead of adding a vector to it (POV-Ray normal.cpp's
/// bump_map and facets).
class NormalSetter {
 public:
  virtual ~NormalSetter() = default;
  /// The bent normal (pattern space, any length) at pattern point p for the unit normal n (pattern space).
  virtual Vec3 set_normal(const Vec3& p, const Vec3& n, double bump_size) const = 0;
};

class BlockPattern {
 public:
  virtual ~BlockPattern() = default;
  /// Which of the `block_count()` entries covers `p`.
  virtual int block(const Vec3& p) const = 0;
  virtual int block_count() const = 0;
};

/// `checker`: unit cubes alternating between two entries. POV-Ray nudges the point by a small tolerance
/// before flooring, so a plane at y=0 does not flicker between cubes through rounding.
class CheckerPattern final : public BlockPattern {
 public:
  int block(const Vec3& p) const override;
  int block_count() const override { return 2; }
};

/// `hexagon`: a tiling of the x-z plane by hexagons of side 1 in three entries, no two neighbours alike;
/// the pattern is constant along y. Entry 0 covers the hexagon centred on the origin.
class HexagonPattern final : public BlockPattern {
 public:
  int block(const Vec3& p) const override;
  int block_count() const override { return 3; }
};

/// `brick`: entry 0 is the mortar, entry 1 the bricks; bricks of `size` (default <8,3,4.5>) in courses
/// offset by half a brick, joints `mortar` wide (default 0.5).
class BrickPattern final : public BlockPattern {
 public:
  explicit BrickPattern(const Vec3& size = {8, 3, 4.5}, double mortar = 0.5);
  int block(const Vec3& p) const override;
  int block_count() const override { return 2; }

 private:
  Vec3 size_;
  double mortar_;
};

}  // namespace snell::texture
