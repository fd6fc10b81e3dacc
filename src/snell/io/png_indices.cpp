#include "snell/io/png_indices.hpp"

#include <zlib.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "snell/io/image_file.hpp"

namespace snell::io {

namespace {

// PNG specification (W3C, 2nd edition, 2003): chunk layout (5.3), IHDR (11.2.2), filters (9.2).
constexpr std::array<unsigned char, 8> kSignature = {137, 80, 78, 71, 13, 10, 26, 10};
/// Larger images are refused rather than allocated (height fields of 16k x 16k are already 256 MB).
constexpr std::uint64_t kMaxPixels = 1ull << 28;

std::uint32_t big_endian(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

int paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

}  // namespace

std::optional<IndexedImage> read_png_indices(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const std::vector<unsigned char> file((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  if (file.size() < 8 || std::memcmp(file.data(), kSignature.data(), 8) != 0) return std::nullopt;
  const auto damaged = [&](const char* why) {
    return ImageIoError(path.string() + ": damaged PNG (" + why + ")");
  };

  IndexedImage image;
  int bit_depth = 0;
  std::vector<unsigned char> compressed;
  for (std::size_t pos = 8; pos + 12 <= file.size();) {
    const std::uint32_t length = big_endian(&file[pos]);
    if (length > file.size() - pos - 12) throw damaged("chunk runs past the end");
    const unsigned char* type = &file[pos + 4];
    const unsigned char* data = &file[pos + 8];
    if (std::memcmp(type, "IHDR", 4) == 0) {
      if (length < 13) throw damaged("short IHDR");
      image.width = static_cast<int>(big_endian(data));
      image.height = static_cast<int>(big_endian(data + 4));
      bit_depth = data[8];
      const int colour_type = data[9], interlace = data[12];
      if (colour_type != 3 || interlace != 0) return std::nullopt;
      if (image.width <= 0 || image.height <= 0 ||
          static_cast<std::uint64_t>(image.width) * static_cast<std::uint64_t>(image.height) > kMaxPixels)
        throw damaged("size out of range");
      if (bit_depth != 1 && bit_depth != 2 && bit_depth != 4 && bit_depth != 8) throw damaged("bit depth");
    } else if (std::memcmp(type, "IDAT", 4) == 0) {
      compressed.insert(compressed.end(), data, data + length);
    } else if (std::memcmp(type, "IEND", 4) == 0) {
      break;
    }
    pos += 12 + length;
  }
  if (bit_depth == 0) return std::nullopt;

  // Each row: one filter byte, then the packed indices.
  const std::size_t stride = (static_cast<std::size_t>(image.width) * bit_depth + 7) / 8;
  const std::size_t rows = static_cast<std::size_t>(image.height);
  std::vector<unsigned char> raw(rows * (stride + 1));
  uLongf raw_size = static_cast<uLongf>(raw.size());
  if (uncompress(raw.data(), &raw_size, compressed.data(), static_cast<uLong>(compressed.size())) != Z_OK ||
      raw_size != raw.size())
    throw damaged("image data does not inflate to its size");

  // Undo the filters; the byte to the left is one byte back, since a pixel is at most one byte here.
  std::vector<unsigned char> previous(stride, 0), row(stride);
  image.indices.resize(rows * static_cast<std::size_t>(image.width));
  const int per_byte = 8 / bit_depth, mask = (1 << bit_depth) - 1;
  for (std::size_t y = 0; y < rows; ++y) {
    const unsigned char* src = &raw[y * (stride + 1)];
    const int filter = src[0];
    for (std::size_t i = 0; i < stride; ++i) {
      const int a = i > 0 ? row[i - 1] : 0, b = previous[i], c = i > 0 ? previous[i - 1] : 0;
      int predictor = 0;
      switch (filter) {
        case 0:
          break;
        case 1:
          predictor = a;
          break;
        case 2:
          predictor = b;
          break;
        case 3:
          predictor = (a + b) / 2;
          break;
        case 4:
          predictor = paeth(a, b, c);
          break;
        default:
          throw damaged("unknown row filter");
      }
      row[i] = static_cast<unsigned char>(src[i + 1] + predictor);
    }
    for (int x = 0; x < image.width; ++x) {
      const int byte = row[static_cast<std::size_t>(x / per_byte)];
      const int shift = 8 - bit_depth * (x % per_byte + 1);
      image.indices[y * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)] =
          static_cast<std::uint8_t>((byte >> shift) & mask);
    }
    std::swap(previous, row);
  }
  return image;
}

}  // namespace snell::io
