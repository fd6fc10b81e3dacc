#pragma once
// A rendered image: linear RGB in float, row-major, top row first.
#include <cstddef>
#include <vector>

#include "snell/math/color.hpp"

namespace snell::io {

struct Image {
  int width = 0;
  int height = 0;
  /// 3 floats per pixel.
  std::vector<float> rgb;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0.0f) {}

  size_t index(int x, int y) const { return (static_cast<size_t>(y) * width + x) * 3; }
  math::Color at(int x, int y) const {
    const size_t i = index(x, y);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  void set(int x, int y, const math::Color& c) {
    const size_t i = index(x, y);
    rgb[i] = static_cast<float>(c.r);
    rgb[i + 1] = static_cast<float>(c.g);
    rgb[i + 2] = static_cast<float>(c.b);
  }
};

}  // namespace snell::io
