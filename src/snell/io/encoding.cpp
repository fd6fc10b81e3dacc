#include "snell/io/encoding.hpp"

#include <algorithm>
#include <cmath>

namespace snell::io {

double srgb_encode(double linear) {
  if (linear <= 0.0031308) return 12.92 * linear;
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double encoded) {
  if (encoded <= 0.04045) return encoded / 12.92;
  return std::pow((encoded + 0.055) / 1.055, 2.4);
}

double Encoding::encode(double value) const {
  if (!(value > 0)) return 0;  // also NaN
  value = std::min(value, 1.0);
  if (passthrough) return value;
  const double linear = assumed_gamma == 1.0 ? value : std::pow(value, assumed_gamma);
  return std::clamp(srgb_encode(linear), 0.0, 1.0);
}

}  // namespace snell::io
