#pragma once
// Image files through OpenImageIO. The format follows the extension: .png (8-bit by default, 16-bit on
// request, encoded with `Encoding`), .exr and .hdr (linear floats, no encoding).
#include <filesystem>
#include <stdexcept>

#include "snell/io/encoding.hpp"
#include "snell/io/image.hpp"

namespace snell::io {

/// Any failure to read or write an image file.
class ImageIoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct WriteOptions {
  Encoding encoding;
  /// 8 or 16 (PNG only).
  int bits = 8;
};

/// Writes to a temporary file in the same folder and renames it over `path`, so a reader never sees a
/// half-written image. Throws ImageIoError.
void write_image(const std::filesystem::path& path, const Image& image, const WriteOptions& options);

/// Reads any format OIIO knows into floats: the file's stored values scaled to [0,1] for integer formats
/// (no decoding curve applied), RGB (grey is replicated) and, when the file has one, alpha. Throws
/// ImageIoError.
Image read_image(const std::filesystem::path& path);

/// Whether writing this format goes through the OpenImageIO plugin (all but PNG, which libpng writes).
bool writes_through_plugin(const std::filesystem::path& path);

/// Whether the extension names a format write_image supports (.png, .exr, .hdr; case-insensitive).
bool is_supported_output(const std::filesystem::path& path);

}  // namespace snell::io
