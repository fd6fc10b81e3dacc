#include "snell/io/image_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <utility>

namespace snell::io {
namespace {

// Signatures from each format's specification: PNG (ISO 15948 section 5.2), JPEG SOI marker and the
// next marker's 0xff (ITU T.81 B.1.1.2), GIF ("GIF87a"/"GIF89a", GIF89a spec section 17), Netpbm "P1" to
// "P6" (netpbm manual pages), TIFF byte-order header (TIFF 6.0 section 2), OpenEXR magic 20000630
// little-endian (OpenEXR file layout), Radiance "#?" (Ward, Graphics Gems II "Real Pixels"), BMP "BM", and
// IFF's "FORM" chunk (EA IFF 85).
struct Signature {
  std::string_view bytes;
  const char* format;
};
constexpr std::array<Signature, 10> kSignatures{{
    {std::string_view("\x89PNG\r\n\x1a\n", 8), "png"},
    {std::string_view("\xff\xd8\xff", 3), "jpeg"},
    {"GIF87a", "gif"},
    {"GIF89a", "gif"},
    {std::string_view("II*\0", 4), "tiff"},
    {std::string_view("MM\0*", 4), "tiff"},
    {std::string_view("\x76\x2f\x31\x01", 4), "openexr"},
    {"#?", "hdr"},
    {"BM", "bmp"},
    {"FORM", "iff"},
}};

constexpr std::array<std::pair<std::string_view, const char*>, 17> kExtensions{{
    {".png", "png"},
    {".jpg", "jpeg"},
    {".jpeg", "jpeg"},
    {".jpe", "jpeg"},
    {".gif", "gif"},
    {".tga", "targa"},
    {".targa", "targa"},
    {".ppm", "pnm"},
    {".pgm", "pnm"},
    {".pbm", "pnm"},
    {".pnm", "pnm"},
    {".tif", "tiff"},
    {".tiff", "tiff"},
    {".exr", "openexr"},
    {".hdr", "hdr"},
    {".bmp", "bmp"},
    {".iff", "iff"},
}};

bool is_netpbm(std::string_view head) {
  return head.size() >= 3 && head[0] == 'P' && head[1] >= '1' && head[1] <= '6' &&
         std::isspace(static_cast<unsigned char>(head[2]));
}

unsigned long little_endian(std::string_view bytes, size_t at, int width) {
  unsigned long value = 0;
  for (int i = width - 1; i >= 0; --i)
    value = (value << 8) | static_cast<unsigned char>(bytes[at + size_t(i)]);
  return value;
}

}  // namespace

long long claimed_pixels(std::string_view head, std::string_view format) {
  // Header layouts: GIF89a spec section 18 (logical screen width and height at bytes 6 to 9), Truevision
  // TGA 2.0 (image width and height at bytes 12 to 15), BMP BITMAPINFOHEADER (int32 width and height at
  // bytes 18 to 25; a negative height means top-down rows).
  if (format == "gif" && head.size() >= 10)
    return static_cast<long long>(little_endian(head, 6, 2)) *
           static_cast<long long>(little_endian(head, 8, 2));
  if (format == "targa" && head.size() >= 16)
    return static_cast<long long>(little_endian(head, 12, 2)) *
           static_cast<long long>(little_endian(head, 14, 2));
  if (format == "bmp" && head.size() >= 26) {
    const auto width = static_cast<std::int32_t>(little_endian(head, 18, 4));
    const auto height = static_cast<std::int32_t>(little_endian(head, 22, 4));
    return std::llabs(static_cast<long long>(width)) * std::llabs(static_cast<long long>(height));
  }
  return -1;
}

std::string image_format_for(std::string_view head, const std::filesystem::path& extension) {
  for (const Signature& signature : kSignatures) {
    if (head.substr(0, signature.bytes.size()) == signature.bytes) return signature.format;
  }
  if (is_netpbm(head)) return "pnm";
  std::string ext = extension.string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const auto& [name, format] : kExtensions)
    if (ext == name) return format;
  return {};
}

ImageFileHeader read_image_header(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::array<char, 32> bytes{};
  in.read(bytes.data(), bytes.size());
  const std::string_view head(bytes.data(), static_cast<size_t>(in.gcount()));
  ImageFileHeader header;
  header.format = image_format_for(head, path.extension());
  header.claimed_pixels = claimed_pixels(head, header.format);
  return header;
}

}  // namespace snell::io
