#pragma once
// The first samples of anti-aliasing's method 1 (aa_neighbours.hpp) traced for a batch of tiles in a pass of
// their own, before any tile of the batch is anti-aliased. A tile then reads the row above it and the column
// to its left from its neighbours' samples instead of tracing them again: with 32-pixel tiles that border
// is 6% more camera rays. A first sample depends only on its pixel (the renderer seeds it by position), so
// the image is the same as when each tile traces its own border; integrators whose samples depend on the
// tile (radiosity's per-tile records) keep that self-contained way.
#include <cstddef>
#include <span>
#include <vector>

#include "snell/math/color.hpp"
#include "snell/render/tiles.hpp"

namespace snell::render {

class FirstSampleGrid {
 public:
  /// The samples `batch` needs in a width x height image: each tile's whole block (full_tile_rect), the row
  /// above it and the column to its left, outside the image too.
  FirstSampleGrid(std::span<const Tile> batch, int width, int height);

  /// Calls visit(x, y) for every sample tile `i` of the batch traces: its block's, and the border samples
  /// that no tile of the batch holds, each given to the first tile of the batch that needs it.
  template <typename Visit>
  void for_each_owned(size_t i, const Visit& visit) const {
    const PixelRect& b = blocks_[i];
    const int me = static_cast<int>(i);
    for (int x = b.x0; x < b.x1; ++x)
      if (owner_[index(x, b.y0 - 1)] == me) visit(x, b.y0 - 1);
    for (int y = b.y0; y < b.y1; ++y) {
      if (owner_[index(b.x0 - 1, y)] == me) visit(b.x0 - 1, y);
      for (int x = b.x0; x < b.x1; ++x) visit(x, y);
    }
  }

  /// The tiles of the batch whose samples tile `i` reads: itself and the owners of its border, the tile
  /// above and the tile to the left where they are in the batch.
  std::vector<size_t> needs(size_t i) const;

  math::Color& at(int x, int y) { return samples_[index(x, y)]; }
  const math::Color& at(int x, int y) const { return samples_[index(x, y)]; }

 private:
  size_t index(int x, int y) const {
    return static_cast<size_t>(y - area_.y0) * static_cast<size_t>(area_.x1 - area_.x0) +
           static_cast<size_t>(x - area_.x0);
  }

  std::vector<PixelRect> blocks_;  // full_tile_rect of each tile of the batch
  PixelRect area_;                 // the blocks' bounding box, one row and one column more above and left
  std::vector<int> owner_;         // index in the batch of the tile that traces each sample, -1 for none
  std::vector<math::Color> samples_;
};

/// `tiles` (in index order) cut into batches of whole rows of tiles whose blocks hold at most `max_pixels`
/// pixels (at least one row each), so that a large image's grids stay small. Each batch after the first
/// traces the row of samples above it again.
std::vector<std::span<const Tile>> tile_batches(std::span<const Tile> tiles, int width, int height,
                                                size_t max_pixels);

}  // namespace snell::render
