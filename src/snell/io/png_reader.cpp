#include "snell/io/png_reader.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "snell/io/image_file.hpp"
#include "snell/io/png_errors.hpp"

namespace snell::io {

namespace {

/// Larger images are refused rather than allocated, as in png_indices.cpp.
constexpr std::uint64_t kMaxPixels = 1ull << 28;

/// Decoded samples, big-endian for 16 bits, rows top first.
struct PngRead {
  std::FILE* file = nullptr;
  PngError error;
  png_uint_32 width = 0, height = 0;
  int channels = 0, bits = 0;
  std::vector<png_byte> samples;
  std::vector<png_bytep> rows;
};

enum class Outcome { decoded, declined, damaged };

/// Chunks after which OpenImageIO's colours differ from the stored samples (it applies gAMA; with tRNS its
/// colours under transparent pixels differ): such files are left to the plugin, so that every image reads
/// the same as before this reader.
constexpr png_uint_32 kLeftToPlugin =
    PNG_INFO_tRNS | PNG_INFO_gAMA | PNG_INFO_sRGB | PNG_INFO_iCCP | PNG_INFO_cHRM;

/// The job's vectors live outside read_png_frame's jump target (png_errors.hpp).
Outcome decode(PngRead& job) {
  return read_png_frame(job.file, job.error, Outcome::damaged, [&job](png_structp png, png_infop info) {
    if (png_get_valid(png, info, kLeftToPlugin) != 0) return Outcome::declined;
    job.width = png_get_image_width(png, info);
    job.height = png_get_image_height(png, info);
    if (std::uint64_t{job.width} * job.height > kMaxPixels) png_error(png, "size out of range");
    png_set_expand(png);  // palette to RGB, grey below 8 bits to 8
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    job.channels = png_get_channels(png, info);
    job.bits = png_get_bit_depth(png, info);
    const std::size_t row_bytes = png_get_rowbytes(png, info);
    job.samples.resize(row_bytes * job.height);
    job.rows.resize(job.height);
    for (png_uint_32 y = 0; y < job.height; ++y) job.rows[y] = &job.samples[row_bytes * y];
    png_read_image(png, job.rows.data());
    return Outcome::decoded;
  });
}

}  // namespace

std::optional<Image> read_png(const std::filesystem::path& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return std::nullopt;
  png_byte signature[8] = {};
  const bool is_png = std::fread(signature, 1, 8, file) == 8 && png_sig_cmp(signature, 0, 8) == 0;
  std::rewind(file);
  if (!is_png) {
    std::fclose(file);
    return std::nullopt;
  }
  PngRead job;
  job.file = file;
  const Outcome outcome = decode(job);
  std::fclose(file);
  if (outcome == Outcome::declined) return std::nullopt;
  if (outcome == Outcome::damaged)
    throw ImageIoError("cannot read '" + path.string() + "': " + job.error.message);
  const auto sample = [&](std::size_t i) {
    return job.bits == 16 ? static_cast<float>(job.samples[2 * i] << 8 | job.samples[2 * i + 1]) / 65535.0f
                          : static_cast<float>(job.samples[i]) / 255.0f;
  };
  Image image(static_cast<int>(job.width), static_cast<int>(job.height));
  const int c = job.channels;
  const bool has_alpha = c == 2 || c == 4;
  if (has_alpha) image.clear_alpha();
  const std::size_t count = std::size_t{job.width} * job.height;
  for (std::size_t p = 0; p < count; ++p) {
    for (int k = 0; k < 3; ++k) image.rgb[p * 3 + k] = sample(p * c + (c < 3 ? 0 : k));
    if (has_alpha) image.alpha[p] = sample(p * c + c - 1);
  }
  return image;
}

}  // namespace snell::io
