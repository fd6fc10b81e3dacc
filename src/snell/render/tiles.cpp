#include "snell/render/tiles.hpp"

#include <algorithm>

namespace snell::render {

int tiles_across(int width) {
  return (width + kTileSize - 1) / kTileSize;
}

int tiles_down(int height) {
  return (height + kTileSize - 1) / kTileSize;
}

PixelRect full_tile_rect(int index, int width, int height) {
  const int across = tiles_across(width);
  const int tx = index % across, ty = index / across;
  return {tx * kTileSize, ty * kTileSize, std::min((tx + 1) * kTileSize, width),
          std::min((ty + 1) * kTileSize, height)};
}

std::vector<Tile> make_tiles(int width, int height, const PixelRect& region) {
  std::vector<Tile> tiles;
  const int across = tiles_across(width), down = tiles_down(height);
  for (int ty = 0; ty < down; ++ty)
    for (int tx = 0; tx < across; ++tx) {
      const PixelRect full = full_tile_rect(ty * across + tx, width, height);
      const PixelRect clipped{std::max(full.x0, region.x0), std::max(full.y0, region.y0),
                              std::min(full.x1, region.x1), std::min(full.y1, region.y1)};
      if (!clipped.empty()) tiles.push_back({ty * across + tx, clipped});
    }
  return tiles;
}

}  // namespace snell::render
