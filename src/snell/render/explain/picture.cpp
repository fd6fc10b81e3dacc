#include "snell/render/explain/picture.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "snell/io/image_file.hpp"
#include "snell/io/png_writer.hpp"

namespace snell::render::explain {

namespace {

constexpr int kGlyphWidth = 3, kGlyphHeight = 5;

/// 3x5 glyphs, five rows of three bits from the top, the leftmost pixel in the high bit; drawn by hand.
uint16_t glyph(char c) {
  auto g = [](int a, int b, int c2, int d, int e) {
    return static_cast<uint16_t>(a << 12 | b << 9 | c2 << 6 | d << 3 | e);
  };
  switch (std::toupper(static_cast<unsigned char>(c))) {
    case '0':
      return g(7, 5, 5, 5, 7);
    case '1':
      return g(2, 6, 2, 2, 7);
    case '2':
      return g(7, 1, 7, 4, 7);
    case '3':
      return g(7, 1, 7, 1, 7);
    case '4':
      return g(5, 5, 7, 1, 1);
    case '5':
      return g(7, 4, 7, 1, 7);
    case '6':
      return g(7, 4, 7, 5, 7);
    case '7':
      return g(7, 1, 1, 2, 2);
    case '8':
      return g(7, 5, 7, 5, 7);
    case '9':
      return g(7, 5, 7, 1, 7);
    case '.':
      return g(0, 0, 0, 0, 2);
    case ',':
      return g(0, 0, 0, 2, 4);
    case '-':
      return g(0, 0, 7, 0, 0);
    case '+':
      return g(0, 2, 7, 2, 0);
    case ':':
      return g(0, 2, 0, 2, 0);
    case '/':
      return g(1, 1, 2, 4, 4);
    case '=':
      return g(0, 7, 0, 7, 0);
    case '(':
      return g(1, 2, 2, 2, 1);
    case ')':
      return g(4, 2, 2, 2, 4);
    case 'A':
      return g(2, 5, 7, 5, 5);
    case 'B':
      return g(6, 5, 6, 5, 6);
    case 'C':
      return g(3, 4, 4, 4, 3);
    case 'D':
      return g(6, 5, 5, 5, 6);
    case 'E':
      return g(7, 4, 6, 4, 7);
    case 'F':
      return g(7, 4, 6, 4, 4);
    case 'G':
      return g(3, 4, 5, 5, 3);
    case 'H':
      return g(5, 5, 7, 5, 5);
    case 'I':
      return g(7, 2, 2, 2, 7);
    case 'J':
      return g(1, 1, 1, 5, 2);
    case 'K':
      return g(5, 5, 6, 5, 5);
    case 'L':
      return g(4, 4, 4, 4, 7);
    case 'M':
      return g(5, 7, 7, 5, 5);
    case 'N':
      return g(6, 5, 5, 5, 5);
    case 'O':
      return g(2, 5, 5, 5, 2);
    case 'P':
      return g(6, 5, 6, 4, 4);
    case 'Q':
      return g(2, 5, 5, 6, 3);
    case 'R':
      return g(6, 5, 6, 5, 5);
    case 'S':
      return g(3, 4, 2, 1, 6);
    case 'T':
      return g(7, 2, 2, 2, 2);
    case 'U':
      return g(5, 5, 5, 5, 7);
    case 'V':
      return g(5, 5, 5, 5, 2);
    case 'W':
      return g(5, 5, 7, 7, 5);
    case 'X':
      return g(5, 5, 2, 5, 5);
    case 'Y':
      return g(5, 5, 2, 2, 2);
    case 'Z':
      return g(7, 1, 2, 4, 7);
    default:
      return 0;
  }
}

}  // namespace

Picture::Picture(int w, int h, Rgb8 fill) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3) {
  fill_rect(0, 0, w, h, fill);
}

void Picture::set(int x, int y, Rgb8 c) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  const size_t i = (static_cast<size_t>(y) * width + x) * 3;
  rgb[i] = c.r, rgb[i + 1] = c.g, rgb[i + 2] = c.b;
}

Rgb8 Picture::at(int x, int y) const {
  const size_t i = (static_cast<size_t>(y) * width + x) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void Picture::fill_rect(int x0, int y0, int x1, int y1, Rgb8 c) {
  for (int y = std::max(y0, 0); y < std::min(y1, height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, width); ++x) set(x, y, c);
}

int Picture::text_width(std::string_view text, int scale) {
  return static_cast<int>(text.size()) * (kGlyphWidth + 1) * scale;
}

int Picture::text(int x, int y, std::string_view text, Rgb8 c, int scale) {
  for (const char ch : text) {
    const uint16_t bits = glyph(ch);
    for (int row = 0; row < kGlyphHeight; ++row)
      for (int col = 0; col < kGlyphWidth; ++col)
        if (bits >> ((kGlyphHeight - 1 - row) * kGlyphWidth + (kGlyphWidth - 1 - col)) & 1)
          fill_rect(x + col * scale, y + row * scale, x + (col + 1) * scale, y + (row + 1) * scale, c);
    x += (kGlyphWidth + 1) * scale;
  }
  return x;
}

Rgb8 to_rgb8(const math::Color& c) {
  auto q = [](double v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  return {q(c.r), q(c.g), q(c.b)};
}

void write_picture(const std::filesystem::path& path, const Picture& picture) {
  std::filesystem::path temp = path;
  temp += fmt::format(".tmp{}.png", getpid());
  const std::string error =
      io::write_png(temp, picture.width, picture.height, 3, 8, picture.rgb.data(), true);
  std::error_code ec;
  if (error.empty()) std::filesystem::rename(temp, path, ec);
  if (!error.empty() || ec) {
    std::filesystem::remove(temp, ec);
    throw io::ImageIoError(
        fmt::format("cannot write {}: {}", path.string(), error.empty() ? "rename failed" : error));
  }
}

}  // namespace snell::render::explain
