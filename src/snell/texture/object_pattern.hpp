#pragma once
// POV-Ray's `object` pattern (reference, "Object Pattern"): two entries, the first outside an object and
// the second inside it; and its `potential` pattern ("Potential Pattern"): the field of a blob or
// isosurface. The object's inside test or field comes in as a function, so textures stay independent of
// the scene's object types.
#include <functional>

#include "snell/texture/pattern.hpp"

namespace snell::texture {

class ObjectPattern final : public BlockPattern {
 public:
  explicit ObjectPattern(std::function<bool(const Vec3&)> inside) : inside_(std::move(inside)) {}
  int block(const Vec3& p) const override { return inside_(p) ? 1 : 0; }
  int block_count() const override { return 2; }

 private:
  std::function<bool(const Vec3&)> inside_;
};

/// `potential { Blob_or_Isosurface } [threshold on]`: the object's field at the point (the blob's summed
/// component densities, the isosurface's function), less the object's threshold with `threshold on`;
/// unbounded, the colour map clips it.
class PotentialPattern final : public ValuePattern {
 public:
  explicit PotentialPattern(std::function<double(const Vec3&)> potential)
      : potential_(std::move(potential)) {}
  double value(const Vec3& p) const override { return potential_(p); }

 private:
  std::function<double(const Vec3&)> potential_;
};

}  // namespace snell::texture
