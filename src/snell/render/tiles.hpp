#pragma once
// The image's division into tiles: the unit of work of threads, of MPI ranks, of checkpoints and of resumed
// renders. Tiles are numbered row by row over the whole image, whatever region is rendered, so a tile index
// means the same pixels in every process and every partial render.
#include <cstdint>
#include <vector>

namespace snell::render {

/// Pixels x0 <= x < x1, y0 <= y < y1.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int64_t area() const { return empty() ? 0 : int64_t{x1 - x0} * (y1 - y0); }
  bool operator==(const PixelRect&) const = default;
};

/// Tile edge in pixels: small enough to balance two to hundreds of cores, large enough that the one-pixel
/// border anti-aliasing re-traces (tile_border.cpp) costs little.
constexpr int kTileSize = 32;

struct Tile {
  /// Index in the full image's row-by-row tiling.
  int index = 0;
  /// The pixels this tile renders (clipped to the region).
  PixelRect rect;
};

/// Number of tiles across and down a width x height image.
int tiles_across(int width);
int tiles_down(int height);

/// The rectangle tile `index` has in a width x height image, clipped to nothing but the image.
PixelRect full_tile_rect(int index, int width, int height);

/// The tiles of a width x height image that meet `region`, clipped to it, in index order.
std::vector<Tile> make_tiles(int width, int height, const PixelRect& region);

}  // namespace snell::render
