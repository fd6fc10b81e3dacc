#include "snell/io/image_file.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <system_error>
#include <vector>

namespace snell::io {

namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

template <typename T>
std::vector<T> quantise(const Image& image, const Encoding& encoding, double max_value) {
  std::vector<T> out(image.rgb.size());
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<T>(std::lround(encoding.encode(image.rgb[i]) * max_value));
  return out;
}

}  // namespace

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

  OIIO::TypeDesc type = OIIO::TypeDesc::FLOAT;
  std::vector<uint8_t> bytes8;
  std::vector<uint16_t> bytes16;
  const void* data = image.rgb.data();
  if (ext == ".png") {
    if (options.bits == 16) {
      bytes16 = quantise<uint16_t>(image, options.encoding, 65535.0);
      type = OIIO::TypeDesc::UINT16;
      data = bytes16.data();
    } else {
      bytes8 = quantise<uint8_t>(image, options.encoding, 255.0);
      type = OIIO::TypeDesc::UINT8;
      data = bytes8.data();
    }
  }
  auto out = OIIO::ImageOutput::create(temp.string());
  if (!out) throw ImageIoError("cannot write '" + path.string() + "': " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 3, type);
  if (ext == ".png") spec.attribute("oiio:ColorSpace", "sRGB");
  if (!out->open(temp.string(), spec) || !out->write_image(type, data) || !out->close()) {
    const std::string why = out->geterror();
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
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw ImageIoError("cannot read '" + path.string() + "': " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || channels <= 0)
    throw ImageIoError("cannot read '" + path.string() + "': empty image");
  std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw ImageIoError("cannot read '" + path.string() + "': " + in->geterror());
  Image image(spec.width, spec.height);
  for (size_t p = 0; p < static_cast<size_t>(spec.width) * spec.height; ++p) {
    for (int c = 0; c < 3; ++c)
      image.rgb[p * 3 + c] = pixels[p * channels + std::min(c, channels < 3 ? 0 : c)];
  }
  return image;
}

}  // namespace snell::io
