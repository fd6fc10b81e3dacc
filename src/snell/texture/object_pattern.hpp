#pragma once
// POV-Ray's `object` pattern (reference, "Object Pattern"): two entries, the first outside an object and
// the second inside it. The object's inside test comes in as a function, so textures stay independent of
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

}  // namespace snell::texture
