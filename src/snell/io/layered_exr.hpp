#pragma once
// Multi-layer OpenEXR output (`snell explain --aov`): any number of named float channels in one file,
// written through the OpenImageIO plugin (oiio_plugin_abi.hpp, SnellOiioWriteChannels).
#include <filesystem>
#include <string>
#include <vector>

namespace snell::io {

/// Writes width x height pixels of `names.size()` interleaved float channels to `path` (.exr) through a
/// temporary file and a rename. Throws ImageIoError.
void write_layered_exr(const std::filesystem::path& path, int width, int height,
                       const std::vector<std::string>& names, const std::vector<float>& pixels);

}  // namespace snell::io
