#pragma once
// POV-Ray's method-1 anti-aliasing test (tracetask.cpp, NonAdaptiveSupersamplingForOnePixel), shared by the
// renderer and the explain layers so that both supersample the same pixels.
#include "snell/render/renderer.hpp"

namespace snell::render {

/// Whether pixel (x, y) of a w x h image differs by at least `threshold` (color_distance) from one of its
/// four neighbours; `encoded(x, y)` is a first-pass colour already through aa_encoded.
template <typename Encoded>
bool differs_from_neighbour(int x, int y, int w, int h, double threshold, const Encoded& encoded) {
  const math::Color c = encoded(x, y);
  const int nx[4] = {x - 1, x + 1, x, x};
  const int ny[4] = {y, y, y - 1, y + 1};
  for (int k = 0; k < 4; ++k)
    if (nx[k] >= 0 && nx[k] < w && ny[k] >= 0 && ny[k] < h &&
        color_distance(c, encoded(nx[k], ny[k])) >= threshold)
      return true;
  return false;
}

}  // namespace snell::render
