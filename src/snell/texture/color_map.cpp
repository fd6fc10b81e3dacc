#include "snell/texture/color_map.hpp"

#include <algorithm>
#include <stdexcept>

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
  if (value <= entries_.front().first) return entries_.front().second;
  if (value >= entries_.back().first) return entries_.back().second;
  const auto upper = std::upper_bound(entries_.begin(), entries_.end(), value,
                                      [](double v, const Entry& e) { return v < e.first; });
  const auto lower = upper - 1;
  const double span = upper->first - lower->first;
  if (span <= 0) return upper->second;
  return material::lerp(lower->second, upper->second, (value - lower->first) / span);
}

}  // namespace snell::texture
