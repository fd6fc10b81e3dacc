#pragma once
#include <utility>
#include <vector>

#include "snell/material/rgbft.hpp"

namespace snell::texture {

/// POV-Ray `color_map { [v colour] ... }`: colours at sorted values, linearly interpolated between them
/// and held constant outside the first and last entries.
class ColorMap {
 public:
  using Entry = std::pair<double, material::Rgbft>;

  explicit ColorMap(std::vector<Entry> entries);
  /// POV-Ray's default map for value patterns without one: a grey ramp from black to white.
  static ColorMap default_map();

  material::Rgbft at(double value) const;
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

}  // namespace snell::texture
