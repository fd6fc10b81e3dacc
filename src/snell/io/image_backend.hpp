#pragma once
// Finds and loads the OpenImageIO plugin (oiio_plugin_abi.hpp) once per process.
#include "snell/io/oiio_plugin_abi.hpp"

namespace snell::io {

struct ImageBackend {
  SnellOiioWrite write = nullptr;
  SnellOiioRead read = nullptr;
  SnellOiioFree free = nullptr;
  /// Null with an older plugin.
  SnellOiioWriteChannels write_channels = nullptr;
};

/// Starts loading the plugin on a background thread; call early (the CLI does at start-up).
void preload_image_backend();
/// The loaded plugin, waiting for a preload in flight. Throws ImageIoError when it cannot be loaded.
const ImageBackend& image_backend();

}  // namespace snell::io
