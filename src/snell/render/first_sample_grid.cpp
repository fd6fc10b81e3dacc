#include "snell/render/first_sample_grid.hpp"

#include <algorithm>

namespace snell::render {

FirstSampleGrid::FirstSampleGrid(std::span<const Tile> batch, int width, int height) {
  blocks_.reserve(batch.size());
  for (const Tile& tile : batch) blocks_.push_back(full_tile_rect(tile.index, width, height));
  if (blocks_.empty()) return;
  area_ = blocks_.front();
  for (const PixelRect& b : blocks_)
    area_ = {std::min(area_.x0, b.x0), std::min(area_.y0, b.y0), std::max(area_.x1, b.x1),
             std::max(area_.y1, b.y1)};
  area_.x0 -= 1;
  area_.y0 -= 1;
  owner_.assign(static_cast<size_t>(area_.area()), -1);
  samples_.resize(owner_.size());
  for (size_t i = 0; i < blocks_.size(); ++i) {
    const PixelRect& b = blocks_[i];
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0; x < b.x1; ++x) owner_[index(x, y)] = static_cast<int>(i);
  }
  // Border samples outside every block: the first tile that compares with one traces it.
  auto claim = [&](int x, int y, size_t i) {
    int& owner = owner_[index(x, y)];
    if (owner < 0) owner = static_cast<int>(i);
  };
  for (size_t i = 0; i < blocks_.size(); ++i) {
    const PixelRect& b = blocks_[i];
    for (int x = b.x0; x < b.x1; ++x) claim(x, b.y0 - 1, i);
    for (int y = b.y0; y < b.y1; ++y) claim(b.x0 - 1, y, i);
  }
}

std::vector<size_t> FirstSampleGrid::needs(size_t i) const {
  const PixelRect& b = blocks_[i];
  std::vector<size_t> needs{i};
  auto need = [&](int x, int y) {
    const auto owner = static_cast<size_t>(owner_[index(x, y)]);
    if (std::find(needs.begin(), needs.end(), owner) == needs.end()) needs.push_back(owner);
  };
  for (int x = b.x0; x < b.x1; ++x) need(x, b.y0 - 1);
  for (int y = b.y0; y < b.y1; ++y) need(b.x0 - 1, y);
  return needs;
}

std::vector<std::span<const Tile>> tile_batches(std::span<const Tile> tiles, int width, int height,
                                                size_t max_pixels) {
  std::vector<std::span<const Tile>> batches;
  const int across = tiles_across(width);
  size_t start = 0, pixels = 0;
  for (size_t row = 0; row < tiles.size();) {
    // One row of tiles: [row, end).
    size_t end = row, row_pixels = 0;
    for (; end < tiles.size() && tiles[end].index / across == tiles[row].index / across; ++end)
      row_pixels += static_cast<size_t>(full_tile_rect(tiles[end].index, width, height).area());
    if (row > start && pixels + row_pixels > max_pixels) {
      batches.push_back(tiles.subspan(start, row - start));
      start = row;
      pixels = 0;
    }
    pixels += row_pixels;
    row = end;
  }
  if (start < tiles.size()) batches.push_back(tiles.subspan(start));
  return batches;
}

}  // namespace snell::render
