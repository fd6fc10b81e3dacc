#include "fuzz/file_fuzzers.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "fuzz/temp_folder.hpp"
#include "snell/io/image_file.hpp"
#include "snell/io/png_indices.hpp"
#include "snell/render/resume_file.hpp"

namespace snell::fuzz {

namespace {

const std::filesystem::path& private_folder() {
  static const std::filesystem::path folder = make_private_folder("snell-file-fuzz");
  return folder;
}

/// Reads an image file as image_map does; false when the reader refuses it with its own error.
bool read_back(const std::string& path) {
  try {
    const io::Image image = io::read_image(path);
    if (image.rgb.size() != size_t(image.width) * size_t(image.height) * 3) std::abort();
    return true;
  } catch (const io::ImageIoError&) {
    return false;
  }
}

template <typename T>
T read_at(const uint8_t* data, size_t offset) {
  T value;
  std::memcpy(&value, data + offset, sizeof value);
  return value;
}

}  // namespace

const char* const kImageFuzzExtensions[] = {".tga", ".ppm", ".gif", ".jpg"};
const size_t kImageFuzzExtensionCount = sizeof kImageFuzzExtensions / sizeof kImageFuzzExtensions[0];

std::string write_fuzz_file(const uint8_t* data, size_t size, const std::string& extension) {
  const std::string path = (private_folder() / ("input" + extension)).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) std::abort();
  return path;
}

bool read_png_bytes(const uint8_t* data, size_t size) {
  const std::string path = write_fuzz_file(data, size, ".png");
  try {
    const auto indexed = io::read_png_indices(path);
    if (indexed && indexed->indices.size() != size_t(indexed->width) * size_t(indexed->height)) std::abort();
  } catch (const io::ImageIoError&) {
    return false;
  }
  return read_back(path);
}

bool read_image_bytes(const uint8_t* data, size_t size) {
  if (size == 0) return false;
  const std::string path =
      write_fuzz_file(data + 1, size - 1, kImageFuzzExtensions[data[0] % kImageFuzzExtensionCount]);
  return read_back(path);
}

bool read_resume_bytes(const uint8_t* data, size_t size) {
  const std::string path = write_fuzz_file(data, size, ".snell-resume");
  // Layout in resume_file.hpp: magic (8), version (4), fingerprint (8), width (4), height (4).
  uint64_t fingerprint = 0;
  int32_t width = 64, height = 64;
  if (size >= 28) {
    fingerprint = read_at<uint64_t>(data, 12);
    width = read_at<int32_t>(data, 20);
    height = read_at<int32_t>(data, 24);
  }
  if (width < 1 || width > 1024) width = 64;
  if (height < 1 || height > 1024) height = 64;
  try {
    const render::ResumeData resumed = render::read_resume_file(path, fingerprint, width, height);
    if (resumed.image.width != width || resumed.image.height != height) std::abort();
    return true;
  } catch (const render::ResumeError&) {
    return false;
  }
}

}  // namespace snell::fuzz
