// snell's OpenImageIO plugin: the only code that includes OpenImageIO (see snell/io/oiio_plugin_abi.hpp).
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "snell/io/oiio_plugin_abi.hpp"

namespace {

int fail(const std::string& message, char* error, size_t error_size) {
  if (error_size > 0) {
    const size_t n = std::min(message.size(), error_size - 1);
    std::memcpy(error, message.data(), n);
    error[n] = '\0';
  }
  return 1;
}

OIIO::TypeDesc type_of(int pixel_type) {
  switch (pixel_type) {
    case kSnellUint8:
      return OIIO::TypeDesc::UINT8;
    case kSnellUint16:
      return OIIO::TypeDesc::UINT16;
    default:
      return OIIO::TypeDesc::FLOAT;
  }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int snell_oiio_write(const char* path, int width,
                                                                       int height, int channels,
                                                                       int pixel_type, const void* pixels,
                                                                       int srgb_tag, char* error,
                                                                       size_t error_size) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return fail(OIIO::geterror(), error, error_size);
  const OIIO::TypeDesc type = type_of(pixel_type);
  OIIO::ImageSpec spec(width, height, channels, type);
  if (channels == 4) {
    spec.alpha_channel = 3;
    // snell's colours are not multiplied by alpha; stop the PNG writer from dividing them by it.
    spec.attribute("oiio:UnassociatedAlpha", 1);
  }
  if (srgb_tag) spec.attribute("oiio:ColorSpace", "sRGB");
  if (!out->open(path, spec) || !out->write_image(type, pixels) || !out->close())
    return fail(out->geterror(), error, error_size);
  return 0;
}

extern "C" __attribute__((visibility("default"))) int snell_oiio_write_channels(
    const char* path, int width, int height, int channels, const char* const* names, const float* pixels,
    char* error, size_t error_size) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return fail(OIIO::geterror(), error, error_size);
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  spec.channelnames.assign(names, names + channels);
  spec.alpha_channel = -1;
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels) || !out->close())
    return fail(out->geterror(), error, error_size);
  return 0;
}

extern "C" __attribute__((visibility("default"))) int snell_oiio_read(const char* path, const char* format,
                                                                      int* width, int* height,
                                                                      int* file_channels, float** pixels,
                                                                      char* error, size_t error_size) {
  // Keep colours as stored (not multiplied by alpha), which is what image maps and merges expect.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  // Only the named format's reader: ImageInput::open would try every other reader on a file this one
  // refuses (snell/io/image_format.hpp). create() without opening does not probe.
  auto in = OIIO::ImageInput::create(format);
  if (!in) return fail(OIIO::geterror(), error, error_size);
  OIIO::ImageSpec spec;
  if (!in->open(path, spec, config)) {
    const std::string why = in->geterror();
    return fail(why.empty() ? std::string("not a readable ") + format + " file" : why, error, error_size);
  }
  const int channels = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || channels <= 0) return fail("empty image", error, error_size);
  const size_t count = static_cast<size_t>(spec.width) * spec.height;
  // A header may claim any size; refuse what would not fit in memory rather than die allocating it.
  constexpr size_t kMaxPixels = size_t{1} << 28;
  if (count > kMaxPixels || channels > 64) return fail("image too large", error, error_size);
  std::vector<float> all(count * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, all.data()))
    return fail(in->geterror(), error, error_size);
  auto* rgba = static_cast<float*>(std::malloc(count * 4 * sizeof(float)));
  if (!rgba) return fail("out of memory", error, error_size);
  // Grey (1 or 2 channels) is replicated; alpha is the spec's alpha channel, or 1 where there is none.
  // A reader may name an alpha channel past the channels it delivers (found by fuzz/image_fuzzer.cpp on a
  // GIF): only a channel that exists is used.
  const int alpha = spec.alpha_channel >= 0 && spec.alpha_channel < channels
                        ? spec.alpha_channel
                        : (channels == 2 || channels >= 4 ? channels - 1 : -1);
  for (size_t p = 0; p < count; ++p) {
    for (int c = 0; c < 3; ++c) rgba[p * 4 + c] = all[p * channels + (channels < 3 ? 0 : c)];
    rgba[p * 4 + 3] = alpha >= 0 ? all[p * channels + alpha] : 1.0f;
  }
  *width = spec.width;
  *height = spec.height;
  *file_channels = channels;
  *pixels = rgba;
  return 0;
}

extern "C" __attribute__((visibility("default"))) void snell_oiio_free(float* pixels) {
  std::free(pixels);
}
