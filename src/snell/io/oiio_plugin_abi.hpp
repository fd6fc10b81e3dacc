#pragma once
// The C interface between snell and its OpenImageIO plugin (src/plugins/oiio_plugin.cpp).
// Why a plugin: Debian's OpenImageIO links about 260 shared libraries (OpenCV, GStreamer, ffmpeg...), whose
// loading and static constructors cost ~0.4 s at every start of a program linked to it. Loaded with dlopen
// on a background thread (io::preload_image_backend), that cost overlaps parsing and rendering.
#include <cstddef>

extern "C" {

/// Pixel types of the interleaved RGB buffers crossing the interface.
enum SnellPixelType { kSnellUint8 = 0, kSnellUint16 = 1, kSnellFloat = 2 };

/// Writes `width` x `height` pixels of `channels` (3: RGB, 4: RGBA) to `path` (format by extension).
/// `srgb_tag` marks the file as sRGB. Returns 0 on success, else writes a message into `error`
/// (NUL-terminated, at most `error_size` bytes).
using SnellOiioWrite = int (*)(const char* path, int width, int height, int channels, int pixel_type,
                               const void* pixels, int srgb_tag, char* error, size_t error_size);
/// Reads an image as interleaved float RGBA (grey replicated; alpha 1 where the file has none) into a buffer
/// from malloc that the caller frees with the plugin's SnellOiioFree. `*file_channels` receives the file's
/// own channel count. `format` names the one OpenImageIO reader to use ("jpeg", "targa": see
/// snell/io/image_format.hpp); no other reader is tried. Returns 0 on success.
using SnellOiioRead = int (*)(const char* path, const char* format, int* width, int* height,
                              int* file_channels, float** pixels, char* error, size_t error_size);
using SnellOiioFree = void (*)(float* pixels);
/// Writes `channels` float channels per pixel, named by `names` ("R", "depth.Z": OpenEXR's layer.channel
/// names), to a multi-layer EXR at `path`. Returns 0 on success.
using SnellOiioWriteChannels = int (*)(const char* path, int width, int height, int channels,
                                       const char* const* names, const float* pixels, char* error,
                                       size_t error_size);
}
