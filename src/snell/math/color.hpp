#pragma once
// Linear RGB colour. POV-Ray's filter and transmit channels travel beside it in material::Rgbft.
#include <algorithm>
#include <cmath>

namespace snell::math {

struct Color {
  double r = 0, g = 0, b = 0;

  constexpr Color() = default;
  constexpr Color(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
  constexpr explicit Color(double s) : r(s), g(s), b(s) {}

  constexpr Color& operator+=(const Color& o) { r += o.r; g += o.g; b += o.b; return *this; }
  constexpr Color& operator-=(const Color& o) { r -= o.r; g -= o.g; b -= o.b; return *this; }
  constexpr Color& operator*=(const Color& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
  constexpr Color& operator*=(double s) { r *= s; g *= s; b *= s; return *this; }
  constexpr bool operator==(const Color&) const = default;

  constexpr double max() const { return std::max(r, std::max(g, b)); }
  constexpr double sum() const { return r + g + b; }
  /// POV-Ray's greyscale weights (colour.h: 0.297, 0.589, 0.114), used by `gray` and adc_bailout.
  constexpr double grey() const { return 0.297 * r + 0.589 * g + 0.114 * b; }
  constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
  bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
};

constexpr Color operator+(Color a, const Color& b) { return a += b; }
constexpr Color operator-(Color a, const Color& b) { return a -= b; }
constexpr Color operator*(Color a, const Color& b) { return a *= b; }
constexpr Color operator*(Color a, double s) { return a *= s; }
constexpr Color operator*(double s, Color a) { return a *= s; }
constexpr Color operator/(Color a, double s) { return a *= 1.0 / s; }
inline Color lerp(const Color& a, const Color& b, double t) { return a * (1 - t) + b * t; }

}  // namespace snell::math
