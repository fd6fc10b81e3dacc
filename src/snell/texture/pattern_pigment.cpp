#include "snell/texture/pattern_pigment.hpp"

#include <algorithm>
#include <stdexcept>

#include "snell/texture/map_bracket.hpp"

namespace snell::texture {

PigmentMap::PigmentMap(std::vector<Entry> entries) : entries_(std::move(entries)) {
  if (entries_.empty()) throw std::invalid_argument("a pigment_map needs at least one entry");
  for (const auto& e : entries_)
    if (!e.second) throw std::invalid_argument("a pigment_map entry has no pigment");
  std::stable_sort(entries_.begin(), entries_.end(),
                   [](const Entry& a, const Entry& b) { return a.first < b.first; });
}

material::Rgbft PigmentMap::at(double value, const material::PatternPoint& point) const {
  const MapBracket b = map_bracket(entries_, value);
  if (b.lower == b.upper) return entries_[b.lower].second->at(point);
  return material::lerp(entries_[b.lower].second->at(point), entries_[b.upper].second->at(point), b.weight);
}

PatternPigment::PatternPigment(PatternSpec spec) : spec_(std::move(spec)) {
  if (!spec_.value_pattern == !spec_.block_pattern)
    throw std::invalid_argument("a pattern pigment needs exactly one pattern");
  if (spec_.block_pattern) {
    if (static_cast<int>(spec_.block_entries.size()) != spec_.block_pattern->block_count())
      throw std::invalid_argument("this pattern takes " + std::to_string(spec_.block_pattern->block_count()) +
                                  " entries");
    for (const auto& e : spec_.block_entries)
      if (!e) throw std::invalid_argument("a pattern entry has no pigment");
  } else if (!spec_.color_map && !spec_.pigment_map) {
    spec_.color_map = ColorMap::default_map();
  }
  may_transmit_ = any_entry_transmits();
}

material::Rgbft PatternPigment::at(const material::PatternPoint& point) const {
  // The entries of a pigment map or block pattern see the point as this pigment's warps left it, as the
  // pattern did (POV-Ray pigment.cpp, Compute_Pigment: Warp_EPoint, then the entry at TPoint).
  material::PatternPoint warped = point;
  warped.p = spec_.warps.apply(point.p);
  const Vec3& p = warped.p;
  if (spec_.block_pattern) return spec_.block_entries[spec_.block_pattern->block(p)]->at(warped);
  const double v =
      spec_.wave.apply(spec_.value_pattern->value_at(p, point.world_normal, point.ray_direction));
  if (spec_.pigment_map) return spec_.pigment_map->at(v, warped);
  return spec_.color_map->at(v);
}

bool PatternPigment::any_entry_transmits() const {
  auto any = [](const auto& pigments, auto pigment_of) {
    for (const auto& entry : pigments)
      if (const PigmentPtr& p = pigment_of(entry); !p || p->may_transmit()) return true;
    return false;
  };
  if (spec_.block_pattern)
    return any(spec_.block_entries, [](const PigmentPtr& p) -> const PigmentPtr& { return p; });
  if (spec_.pigment_map)
    return any(spec_.pigment_map->entries(),
               [](const PigmentMap::Entry& e) -> const PigmentPtr& { return e.second; });
  if (!spec_.color_map) return true;
  for (const ColorMap::Entry& entry : spec_.color_map->entries())
    if (entry.second.is_transparent()) return true;
  return false;
}

material::Rgbft TransformedPigment::at(const material::PatternPoint& point) const {
  material::PatternPoint moved = point;
  moved.p = transform_.inverse_point(point.p);
  return inner_->at(moved);
}

material::Rgbft UvMappedPigment::at(const material::PatternPoint& point) const {
  material::PatternPoint uv = point;
  uv.p = Vec3{point.uv.u, point.uv.v, 0};
  return inner_->at(uv);
}

PigmentPtr transform_pigment(const PigmentPtr& pigment, const math::Transform& transform) {
  if (!pigment || pigment->is_constant() || transform.is_identity()) return pigment;
  return std::make_shared<TransformedPigment>(pigment, transform);
}

}  // namespace snell::texture
