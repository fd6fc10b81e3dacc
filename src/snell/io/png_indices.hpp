#pragma once
// Palette indices of an indexed-colour PNG. POV-Ray's height_field takes a palette image's index, not its
// colour, as the height (imageutil.cpp, image_height_at), and OpenImageIO only hands out colours.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace snell::io {

struct IndexedImage {
  int width = 0;
  int height = 0;
  /// Row-major from the top row, one palette index per pixel.
  std::vector<std::uint8_t> indices;
};

/// The indices when `path` is a non-interlaced palette PNG (colour type 3, 1 to 8 bits); nullopt for any
/// other PNG or file. Throws ImageIoError for a palette PNG that is damaged.
std::optional<IndexedImage> read_png_indices(const std::filesystem::path& path);

}  // namespace snell::io
