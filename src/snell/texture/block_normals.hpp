#pragma once
// Block patterns (checker, hexagon, brick, object) in a normal (POV-Ray 3.7 reference, "Normal", "Block
// Patterns"): with a normal per block, `normal { checker normal {A} normal {B} }` bends the surface by the
// block's own normal; without a list, the block number is the pattern's value, so the surface steps at
// the blocks' edges (over the bump's finite-difference width), as POV-Ray bumps mortar lines.
#include <vector>

#include "snell/texture/pattern_normal.hpp"

namespace snell::texture {

/// The block number as a value (checker 0 or 1, brick 0 brick / 1 mortar, hexagon 0 to 2).
class BlockValuePattern final : public ValuePattern {
 public:
  explicit BlockValuePattern(std::shared_ptr<const BlockPattern> blocks) : blocks_(std::move(blocks)) {}
  double value(const Vec3& p) const override { return blocks_->block(p); }

 private:
  std::shared_ptr<const BlockPattern> blocks_;
};

class BlockNormal final : public material::Normal {
 public:
  /// Throws std::invalid_argument when `entries` does not hold one normal per block.
  BlockNormal(std::shared_ptr<const BlockPattern> blocks, WarpList warps, std::vector<NormalPtr> entries);
  math::Vec3 perturb(const math::Vec3& normal, const material::PatternPoint& point) const override;

 private:
  std::shared_ptr<const BlockPattern> blocks_;
  WarpList warps_;
  std::vector<NormalPtr> entries_;
};

}  // namespace snell::texture
