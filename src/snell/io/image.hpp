#pragma once
// A rendered image: linear RGB in float, row-major, top row first, with an optional coverage channel.
#include <cstddef>
#include <vector>

#include "snell/math/color.hpp"

namespace snell::io {

struct Image {
  int width = 0;
  int height = 0;
  /// 3 floats per pixel.
  std::vector<float> rgb;
  /// Empty, or one value per pixel: 1 where the pixel was rendered, 0 where it was not (a partial render, an
  /// interrupted one). Files then carry it as an alpha channel, so merged parts and resumed renders know
  /// which pixels are real (issue 12, "unrendered pixels marked").
  std::vector<float> alpha;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0.0f) {}

  size_t index(int x, int y) const { return (static_cast<size_t>(y) * width + x) * 3; }
  math::Color at(int x, int y) const {
    const size_t i = index(x, y);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  bool has_alpha() const { return !alpha.empty(); }
  /// Starts the coverage channel with every pixel unrendered.
  void clear_alpha() { alpha.assign(static_cast<size_t>(width) * height, 0.0f); }
  /// No coverage channel, or every pixel rendered.
  bool fully_covered() const {
    for (float a : alpha)
      if (a < 1.0f) return false;
    return true;
  }
  /// Drops the coverage channel when it says nothing (every pixel rendered), so files stay RGB.
  void drop_alpha_if_covered() {
    if (fully_covered()) alpha.clear();
  }
  float alpha_at(int x, int y) const {
    return alpha.empty() ? 1.0f : alpha[static_cast<size_t>(y) * width + x];
  }
  void set_alpha(int x, int y, float a) { alpha[static_cast<size_t>(y) * width + x] = a; }

  void set(int x, int y, const math::Color& c) {
    const size_t i = index(x, y);
    rgb[i] = static_cast<float>(c.r);
    rgb[i + 1] = static_cast<float>(c.g);
    rgb[i + 2] = static_cast<float>(c.b);
  }
};

}  // namespace snell::io
