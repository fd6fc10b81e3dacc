#pragma once
// An 8-bit RGB picture to draw legends into, with a tiny built-in 3x5 bitmap font (capitals, digits and a
// few signs; lower case is drawn as capitals) so legends need no font files.
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "snell/math/color.hpp"

namespace snell::render::explain {

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
};

struct Picture {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;

  Picture(int w, int h, Rgb8 fill = {});
  void set(int x, int y, Rgb8 c);
  Rgb8 at(int x, int y) const;
  void fill_rect(int x0, int y0, int x1, int y1, Rgb8 c);
  /// Draws `text` with its top-left corner at (x, y), each font pixel `scale` x `scale`; returns the x after
  /// the last glyph. Characters the font lacks are drawn as spaces.
  int text(int x, int y, std::string_view text, Rgb8 c, int scale = 2);
  /// Width in pixels `text` takes at `scale`.
  static int text_width(std::string_view text, int scale = 2);
};

/// A colour from 0..1 (clamped) in 8 bits.
Rgb8 to_rgb8(const math::Color& c);

/// Writes `picture` as PNG through a temporary file and a rename. Throws io::ImageIoError.
void write_picture(const std::filesystem::path& path, const Picture& picture);

}  // namespace snell::render::explain
