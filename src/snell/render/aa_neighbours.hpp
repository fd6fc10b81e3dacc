#pragma once
// POV-Ray's method-1 anti-aliasing over one render block (tracetask.cpp, NonAdaptiveSupersamplingM1 and
// NonAdaptiveSupersamplingForOnePixel), shared by the renderer and the explain layers so that both
// supersample the same pixels.
//
// POV-Ray walks a block row by row. Each pixel's first sample is compared with its left and top
// neighbours' colours as they are by then (a neighbour already supersampled counts with its supersampled
// colour); where one differs by at least the threshold, the pixel is supersampled, and so is that neighbour
// unless it was already. The row above the block and the column to its left are first samples seen only
// for comparison, never supersampled by this block (outside the image too: POV-Ray traces them there).
// A block's result therefore depends on nothing outside it but those first samples.
#include <cstddef>
#include <vector>

#include "snell/render/renderer.hpp"
#include "snell/render/tiles.hpp"

namespace snell::render {

/// Runs POV-Ray's method-1 test over `block`. `first(x, y)` is the first-sample colour of any pixel of the
/// block, of the row above it or of the column left of it; `supersample(x, y, c)` returns pixel (x, y)'s
/// colour after supersampling, `c` being its first sample. Colours are compared through aa_encoded with
/// `exponent`. `out` receives the block's colours row by row; `refined` (same layout) which were
/// supersampled.
template <typename First, typename Supersample>
void supersample_block(const PixelRect& block, double threshold, double exponent, const First& first,
                       const Supersample& supersample, std::vector<math::Color>& out,
                       std::vector<char>& refined) {
  const int bw = block.x1 - block.x0, bh = block.y1 - block.y0;
  // The block with one more row above and one more column to the left: cell (x, y) at (x + 1, y + 1).
  const int gw = bw + 1;
  std::vector<math::Color> colour(static_cast<size_t>(gw) * (bh + 1)), encoded(colour.size());
  std::vector<char> done(colour.size(), 0);
  auto cell = [&](int x, int y) { return static_cast<size_t>(y - block.y0 + 1) * gw + (x - block.x0 + 1); };
  auto set = [&](size_t i, const math::Color& c) {
    colour[i] = c;
    encoded[i] = aa_encoded(c, exponent);
  };
  for (int x = block.x0; x < block.x1; ++x) {
    set(cell(x, block.y0 - 1), first(x, block.y0 - 1));
    done[cell(x, block.y0 - 1)] = 1;
  }
  for (int y = block.y0; y < block.y1; ++y) {
    set(cell(block.x0 - 1, y), first(block.x0 - 1, y));
    done[cell(block.x0 - 1, y)] = 1;
    for (int x = block.x0; x < block.x1; ++x) {
      const size_t c = cell(x, y), left = cell(x - 1, y), top = cell(x, y - 1);
      set(c, first(x, y));
      const bool left_differs = color_distance(encoded[left], encoded[c]) >= threshold;
      const bool top_differs = color_distance(encoded[top], encoded[c]) >= threshold;
      if (left_differs && !done[left]) {
        set(left, supersample(x - 1, y, colour[left]));
        done[left] = 1;
      }
      if (top_differs && !done[top]) {
        set(top, supersample(x, y - 1, colour[top]));
        done[top] = 1;
      }
      if (left_differs || top_differs) {
        set(c, supersample(x, y, colour[c]));
        done[c] = 1;
      }
    }
  }
  out.resize(static_cast<size_t>(bw) * bh);
  refined.resize(out.size());
  for (int y = block.y0; y < block.y1; ++y)
    for (int x = block.x0; x < block.x1; ++x) {
      const size_t i = static_cast<size_t>(y - block.y0) * bw + (x - block.x0);
      out[i] = colour[cell(x, y)];
      refined[i] = done[cell(x, y)];
    }
}

}  // namespace snell::render
