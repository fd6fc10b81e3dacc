// Read with libpng (already snell's PNG writer, png_writer.cpp), which unpacks 1-, 2- and 4-bit indices to
// one byte each without expanding them through the palette.
#include "snell/io/png_indices.hpp"

#include <cstdio>

#include "snell/io/image_file.hpp"
#include "snell/io/png_errors.hpp"

namespace snell::io {

namespace {

/// Larger images are refused rather than allocated (height fields of 16k x 16k are already 256 MB).
constexpr std::uint64_t kMaxPixels = 1ull << 28;

enum class Outcome { indexed, not_indexed, damaged };

/// libpng reports errors by longjmp: the jump target below holds only trivially destructible state, and
/// the output vector is sized before the jump target is set.
struct PngRead {
  std::FILE* file;
  IndexedImage* image;
  PngError error;
};

Outcome decode(PngRead& job) {
  return read_png_frame(job.file, job.error, Outcome::damaged, [&job](png_structp png, png_infop info) {
    if (png_get_color_type(png, info) != PNG_COLOR_TYPE_PALETTE ||
        png_get_interlace_type(png, info) != PNG_INTERLACE_NONE)
      return Outcome::not_indexed;
    const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    if (std::uint64_t{width} * height > kMaxPixels) png_error(png, "size out of range");
    png_set_packing(png);  // one index per byte
    png_read_update_info(png, info);
    job.image->width = static_cast<int>(width);
    job.image->height = static_cast<int>(height);
    job.image->indices.resize(std::size_t{width} * height);
    for (png_uint_32 y = 0; y < height; ++y)
      png_read_row(png, &job.image->indices[std::size_t{y} * width], nullptr);
    return Outcome::indexed;
  });
}

}  // namespace

std::optional<IndexedImage> read_png_indices(const std::filesystem::path& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return std::nullopt;
  png_byte signature[8] = {};
  if (std::fread(signature, 1, sizeof signature, file) != sizeof signature ||
      png_sig_cmp(signature, 0, sizeof signature) != 0) {
    std::fclose(file);
    return std::nullopt;
  }
  std::rewind(file);
  IndexedImage image;
  PngRead job{file, &image, {}};
  const Outcome outcome = decode(job);
  std::fclose(file);
  if (outcome == Outcome::damaged)
    throw ImageIoError(path.string() + ": damaged PNG (" +
                       (job.error.message[0] ? job.error.message : "unreadable") + ")");
  if (outcome == Outcome::not_indexed) return std::nullopt;
  return image;
}

}  // namespace snell::io
