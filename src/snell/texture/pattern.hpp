#pragma once
// POV-Ray patterns (POV-Ray 3.7 reference, "Patterns"). Two families:
// - value patterns map a point to a number in [0,1] that a colour/pigment map turns into colour;
// - block patterns (checker, hexagon, brick) pick one of a fixed list of pigments.
#include <memory>

#include "snell/math/vec3.hpp"

namespace snell::texture {

using math::Vec3;

class ValuePattern {
 public:
  virtual ~ValuePattern() = default;
  /// The pattern's value at `p` (texture space), in [0,1] before the wave function.
  virtual double value(const Vec3& p) const = 0;
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

/// `gradient <v>`: the value grows along v, repeating every 1/|v| units (ramp wave by default).
class GradientPattern final : public ValuePattern {
 public:
  explicit GradientPattern(const Vec3& direction) : direction_(direction) {}
  double value(const Vec3& p) const override;

 private:
  Vec3 direction_;
};

}  // namespace snell::texture
