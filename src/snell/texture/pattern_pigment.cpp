#include "snell/texture/pattern_pigment.hpp"

#include <algorithm>
#include <stdexcept>

namespace snell::texture {

PigmentMap::PigmentMap(std::vector<Entry> entries) : entries_(std::move(entries)) {
  if (entries_.empty()) throw std::invalid_argument("a pigment_map needs at least one entry");
  for (const auto& e : entries_)
    if (!e.second) throw std::invalid_argument("a pigment_map entry has no pigment");
  std::stable_sort(entries_.begin(), entries_.end(),
                   [](const Entry& a, const Entry& b) { return a.first < b.first; });
}

material::Rgbft PigmentMap::at(double value, const material::PatternPoint& point) const {
  if (value <= entries_.front().first) return entries_.front().second->at(point);
  if (value >= entries_.back().first) return entries_.back().second->at(point);
  const auto upper = std::upper_bound(entries_.begin(), entries_.end(), value,
                                      [](double v, const Entry& e) { return v < e.first; });
  const auto lower = upper - 1;
  const double span = upper->first - lower->first;
  if (span <= 0) return upper->second->at(point);
  const double t = (value - lower->first) / span;
  return material::lerp(lower->second->at(point), upper->second->at(point), t);
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
}

material::Rgbft PatternPigment::at(const material::PatternPoint& point) const {
  const Vec3 p = spec_.warps.apply(point.p);
  if (spec_.block_pattern) return spec_.block_entries[spec_.block_pattern->block(p)]->at(point);
  const double v = spec_.wave.apply(spec_.value_pattern->value(p));
  if (spec_.pigment_map) return spec_.pigment_map->at(v, point);
  return spec_.color_map->at(v);
}

material::Rgbft TransformedPigment::at(const material::PatternPoint& point) const {
  material::PatternPoint moved = point;
  moved.p = transform_.inverse_point(point.p);
  return inner_->at(moved);
}

PigmentPtr transform_pigment(const PigmentPtr& pigment, const math::Transform& transform) {
  if (!pigment || pigment->is_constant() || transform.is_identity()) return pigment;
  return std::make_shared<TransformedPigment>(pigment, transform);
}

}  // namespace snell::texture
