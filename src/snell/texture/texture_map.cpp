#include "snell/texture/texture_map.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "snell/texture/map_bracket.hpp"

namespace snell::texture {

PatternTextureSelector::PatternTextureSelector(PatternSpec pattern,
                                               std::vector<std::pair<double, TexturePtr>> map,
                                               std::vector<TexturePtr> blocks)
    : pattern_(std::move(pattern)), map_(std::move(map)), blocks_(std::move(blocks)) {
  if (!pattern_.value_pattern == !pattern_.block_pattern)
    throw std::invalid_argument("a patterned texture needs exactly one pattern");
  if (pattern_.block_pattern) {
    if (static_cast<int>(blocks_.size()) != pattern_.block_pattern->block_count())
      throw std::invalid_argument("this pattern takes " +
                                  std::to_string(pattern_.block_pattern->block_count()) + " textures");
  } else if (map_.empty()) {
    throw std::invalid_argument("a texture_map needs at least one entry");
  }
  for (const auto& e : map_)
    if (!e.second) throw std::invalid_argument("a texture_map entry has no texture");
  for (const auto& e : blocks_)
    if (!e) throw std::invalid_argument("a pattern entry has no texture");
  std::stable_sort(map_.begin(), map_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}

material::TextureSelector::Choice PatternTextureSelector::at(const material::PatternPoint& point) const {
  const Vec3 p = pattern_.warps.apply(point.p);
  if (pattern_.block_pattern)
    return {blocks_[static_cast<size_t>(pattern_.block_pattern->block(p))].get(), nullptr, 0, p};
  const double v =
      pattern_.wave.apply(pattern_.value_pattern->value_at(p, point.world_normal, point.ray_direction));
  const MapBracket b = map_bracket(map_, v);
  if (b.lower == b.upper) return {map_[b.lower].second.get(), nullptr, 0, p};
  return {map_[b.lower].second.get(), map_[b.upper].second.get(), b.weight, p};
}

}  // namespace snell::texture
