#include "snell/io/image_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "snell/io/byte_encoding.hpp"
#include "snell/io/image_backend.hpp"
#include "snell/io/image_format.hpp"
#include "snell/io/png_reader.hpp"
#include "snell/io/png_writer.hpp"

namespace snell::io {

namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// Interleaved RGB or RGBA (when the image has a coverage channel) as written to the file. Colours pass
/// through `encode`; alpha is stored linearly, as every format defines it.
template <typename T, typename Encode>
std::vector<T> interleave(const Image& image, Encode encode) {
  const int channels = image.has_alpha() ? 4 : 3;
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  std::vector<T> out(pixels * channels);
  for (size_t p = 0; p < pixels; ++p) {
    for (int c = 0; c < 3; ++c) out[p * channels + c] = encode(image.rgb[p * 3 + c], false);
    if (channels == 4) out[p * channels + 3] = encode(image.alpha[p], true);
  }
  return out;
}

template <typename T>
std::vector<T> quantise(const Image& image, const Encoding& encoding, double max_value) {
  return interleave<T>(image, [&](float v, bool is_alpha) {
    return static_cast<T>(std::lround((is_alpha ? v : encoding.encode(v)) * max_value));
  });
}

}  // namespace

bool writes_through_plugin(const fs::path& path) {
  return lower_extension(path) != ".png";
}

bool is_supported_output(const fs::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".png" || ext == ".exr" || ext == ".hdr";
}

void write_image(const fs::path& path, const Image& image, const WriteOptions& options) {
  const std::string ext = lower_extension(path);
  if (!is_supported_output(path))
    throw ImageIoError("cannot write '" + path.string() + "': unsupported image format '" + ext +
                       "' (use .png, .exr or .hdr)");
  if (image.width <= 0 || image.height <= 0) throw ImageIoError("cannot write an empty image");
  // Same folder, so the final rename cannot cross file systems; keep the extension for OIIO's format choice.
  std::string temp_name = path.stem().string();
  temp_name.insert(0, 1, '.');
  temp_name.append(".snell-tmp");
  temp_name.append(ext);
  const fs::path temp = path.parent_path() / temp_name;

  int type = kSnellFloat;
  std::vector<uint8_t> bytes8;
  std::vector<uint16_t> bytes16;
  std::vector<float> floats;
  const void* data = image.rgb.data();
  if (ext != ".png" && image.has_alpha()) {
    floats = interleave<float>(image, [](float v, bool) { return v; });
    data = floats.data();
  }
  if (ext == ".png") {
    if (options.bits == 16) {
      bytes16 = quantise<uint16_t>(image, options.encoding, 65535.0);
      type = kSnellUint16;
      data = bytes16.data();
    } else {
      const ByteEncoding byte(options.encoding);
      bytes8 = interleave<uint8_t>(image, [&](float v, bool is_alpha) {
        return is_alpha ? static_cast<uint8_t>(std::lround(static_cast<double>(v) * 255.0)) : byte(v);
      });
      type = kSnellUint8;
      data = bytes8.data();
    }
  }
  const int channels = image.has_alpha() ? 4 : 3;
  std::string why;
  if (ext == ".png") {
    why = write_png(temp, image.width, image.height, channels, options.bits == 16 ? 16 : 8, data, true);
  } else {
    char message[512] = {};
    if (image_backend().write(temp.c_str(), image.width, image.height, channels, type, data, 0, message,
                              sizeof message) != 0)
      why = message[0] ? message : "unknown error";
  }
  if (!why.empty()) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw ImageIoError("cannot write '" + path.string() + "': " + why);
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw ImageIoError("cannot write '" + path.string() + "': " + ec.message());
  }
}

Image read_image(const fs::path& path) {
  if (std::optional<Image> png = read_png(path)) return std::move(*png);  // no plugin to load for PNG
  const ImageFileHeader header = read_image_header(path);
  const std::string& format = header.format;
  if (format.empty())
    throw ImageIoError("cannot read '" + path.string() +
                       "': not an image format snell knows by its first bytes or its extension");
  if (header.claimed_pixels > kMaxClaimedPixels)
    throw ImageIoError("cannot read '" + path.string() + "': its header claims " +
                       std::to_string(header.claimed_pixels) + " pixels, more than the " +
                       std::to_string(kMaxClaimedPixels) + " snell accepts");
  const ImageBackend& backend = image_backend();
  int width = 0, height = 0, channels = 0;
  float* pixels = nullptr;
  char why[512] = {};
  if (backend.read(path.c_str(), format.c_str(), &width, &height, &channels, &pixels, why, sizeof why) != 0)
    throw ImageIoError("cannot read '" + path.string() + "': " + why);
  Image image(width, height);
  const bool has_alpha = channels == 2 || channels >= 4;
  if (has_alpha) image.clear_alpha();
  const size_t count = static_cast<size_t>(width) * height;
  for (size_t p = 0; p < count; ++p) {
    for (int c = 0; c < 3; ++c) image.rgb[p * 3 + c] = pixels[p * 4 + c];
    if (has_alpha) image.alpha[p] = pixels[p * 4 + 3];
  }
  backend.free(pixels);
  return image;
}

}  // namespace snell::io
