#include "snell/texture/block_normals.hpp"

#include <stdexcept>

namespace snell::texture {

BlockNormal::BlockNormal(std::shared_ptr<const BlockPattern> blocks, WarpList warps,
                         std::vector<NormalPtr> entries)
    : blocks_(std::move(blocks)), warps_(std::move(warps)), entries_(std::move(entries)) {
  if (!blocks_ || static_cast<int>(entries_.size()) != blocks_->block_count())
    throw std::invalid_argument("a block pattern needs one normal per block");
}

math::Vec3 BlockNormal::perturb(const math::Vec3& normal, const material::PatternPoint& point) const {
  // As with pigments, the block is chosen at the warped point and its normal sees that point (POV-Ray
  // normal.cpp, Perturb_Normal).
  material::PatternPoint warped = point;
  warped.p = warps_.apply(point.p);
  const NormalPtr& entry = entries_[static_cast<std::size_t>(blocks_->block(warped.p))];
  return entry ? entry->perturb(normal, warped) : normal;
}

}  // namespace snell::texture
