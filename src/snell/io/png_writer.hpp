#pragma once
// PNG output with libpng directly. Why not through the OpenImageIO plugin: loading OpenImageIO and its ~260
// libraries costs ~0.4 s of CPU and, while the dynamic loader holds its lock, stalls the render threads'
// start; PNG is the default output of every render, so it must not pay for that (image_backend.hpp).
#include <cstdint>
#include <filesystem>
#include <string>

namespace snell::io {

/// Writes interleaved 8-bit (`bits` 8) or 16-bit (`bits` 16, native byte order) samples, 3 (RGB) or 4 (RGBA)
/// channels, tagged as sRGB when `srgb`. Returns an empty string on success, else the reason.
std::string write_png(const std::filesystem::path& path, int width, int height, int channels, int bits,
                      const void* pixels, bool srgb);

}  // namespace snell::io
