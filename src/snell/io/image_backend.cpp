#include "snell/io/image_backend.hpp"

#include <future>
#include <mutex>
#include <string>
#include <vector>

#include "snell/io/image_file.hpp"
#include "snell/io/plugin_loader.hpp"

namespace snell::io {

namespace {

constexpr const char* kPluginName = "libsnell_oiio.so";

struct LoadResult {
  ImageBackend backend;
  std::string error;
};

LoadResult load() {
  LoadResult result;
  void* handle = open_plugin(kPluginName, result.error);
  if (!handle) return result;
  result.backend.write = reinterpret_cast<SnellOiioWrite>(plugin_symbol(handle, "snell_oiio_write"));
  result.backend.read = reinterpret_cast<SnellOiioRead>(plugin_symbol(handle, "snell_oiio_read"));
  result.backend.free = reinterpret_cast<SnellOiioFree>(plugin_symbol(handle, "snell_oiio_free"));
  result.backend.write_channels =
      reinterpret_cast<SnellOiioWriteChannels>(plugin_symbol(handle, "snell_oiio_write_channels"));
  if (!result.backend.write || !result.backend.read || !result.backend.free) {
    result.error = std::string(kPluginName) + " lacks the snell_oiio_* entry points";
    result.backend = {};
  }
  return result;
}

std::once_flag g_started;
std::shared_future<LoadResult> g_loading;

}  // namespace

void preload_image_backend() {
  std::call_once(g_started, [] { g_loading = std::async(std::launch::async, load).share(); });
}

const ImageBackend& image_backend() {
  preload_image_backend();
  const LoadResult& r = g_loading.get();
  if (!r.backend.write) throw ImageIoError("cannot load the image plugin: " + r.error);
  return r.backend;
}

}  // namespace snell::io
