#pragma once
// The lookup every POV-Ray map shares (colour, pigment, normal, slope and texture maps; POV-Ray 3.7
// reference, "Color Maps"): entries sorted by value, the two around a value blended linearly, the
// first and last held beyond the ends, and the later of two entries at the same value winning.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace snell::texture {

/// Entries `lower` and `upper` around a value, `weight` of upper in [0,1]; lower == upper when one
/// entry covers the value.
struct MapBracket {
  size_t lower;
  size_t upper;
  double weight;
};

/// `key(entry)` gives an entry's value; `entries` are sorted by it and not empty.
template <class Entry, class Key>
MapBracket map_bracket(const std::vector<Entry>& entries, double value, Key key) {
  const size_t last = entries.size() - 1;
  if (value <= key(entries.front())) return {0, 0, 0};
  if (value >= key(entries.back())) return {last, last, 0};
  const auto upper_it = std::upper_bound(entries.begin(), entries.end(), value,
                                         [&](double v, const Entry& e) { return v < key(e); });
  const auto upper = static_cast<size_t>(upper_it - entries.begin());
  const size_t lower = upper - 1;
  const double span = key(entries[upper]) - key(entries[lower]);
  if (span <= 0) return {upper, upper, 0};
  return {lower, upper, (value - key(entries[lower])) / span};
}

/// For the usual (value, thing) pair entries.
template <class Entry>
MapBracket map_bracket(const std::vector<Entry>& entries, double value) {
  return map_bracket(entries, value, [](const Entry& e) { return e.first; });
}

}  // namespace snell::texture
