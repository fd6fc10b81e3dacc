#pragma once
#include "snell/math/color.hpp"

namespace snell::material {

/// A POV-Ray colour: linear RGB with `filter` (light passing through, tinted by the colour) and
/// `transmit` (light passing through untinted).
struct Rgbft {
  math::Color rgb;
  double filter = 0;
  double transmit = 0;

  constexpr bool operator==(const Rgbft&) const = default;
  /// True when the surface lets any light through.
  constexpr bool is_transparent() const { return filter > 0 || transmit > 0; }
};

/// Linear blend of all five channels, as colour and pigment maps interpolate their entries.
inline Rgbft lerp(const Rgbft& a, const Rgbft& b, double t) {
  return {math::lerp(a.rgb, b.rgb, t), a.filter + (b.filter - a.filter) * t,
          a.transmit + (b.transmit - a.transmit) * t};
}

}  // namespace snell::material
