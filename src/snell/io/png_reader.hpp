#pragma once
// PNG files read with libpng directly. Every image_map and height_field used to go through the OpenImageIO
// plugin, whose loading (about 280 shared libraries, GDAL among them) costs 0.4 s on an idle machine and
// seconds on a busy one: more than the whole render of POV-Ray's textures/pigments/pigment.pov.
#include <filesystem>
#include <optional>

#include "snell/io/image.hpp"

namespace snell::io {

/// The image when `path` is a PNG without tRNS, gAMA, sRGB, iCCP or cHRM chunks: colours as stored (palette
/// expanded, grey replicated, 8 and 16 bits scaled to [0, 1]) and alpha from the alpha channel, exactly as
/// the OpenImageIO plugin gives them. nullopt for any other file (read through the plugin); throws
/// ImageIoError for a damaged PNG.
std::optional<Image> read_png(const std::filesystem::path& path);

}  // namespace snell::io
