#include "snell/texture/color_map.hpp"

#include <algorithm>
#include <stdexcept>

#include "snell/texture/map_bracket.hpp"

namespace snell::texture {

ColorMap::ColorMap(std::vector<Entry> entries) : entries_(std::move(entries)) {
  if (entries_.empty()) throw std::invalid_argument("a color_map needs at least one entry");
  std::stable_sort(entries_.begin(), entries_.end(),
                   [](const Entry& a, const Entry& b) { return a.first < b.first; });
}

ColorMap ColorMap::default_map() {
  return ColorMap(
      {{0.0, material::Rgbft{math::Color(0), 0, 0}}, {1.0, material::Rgbft{math::Color(1), 0, 0}}});
}

material::Rgbft ColorMap::at(double value) const {
  const MapBracket b = map_bracket(entries_, value);
  if (b.lower == b.upper) return entries_[b.lower].second;
  return material::lerp(entries_[b.lower].second, entries_[b.upper].second, b.weight);
}

}  // namespace snell::texture
