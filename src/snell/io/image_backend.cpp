#include "snell/io/image_backend.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <future>
#include <mutex>
#include <string>
#include <vector>

#include "snell/io/image_file.hpp"

namespace snell::io {

namespace {

constexpr const char* kPluginName = "libsnell_oiio.so";

struct LoadResult {
  ImageBackend backend;
  std::string error;
};

/// Beside the running program first (the snell binary and its plugin live in one folder), then the build
/// folder this library was compiled for (test programs live one folder below it).
std::vector<std::filesystem::path> candidates() {
  std::vector<std::filesystem::path> paths;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back(exe.parent_path() / kPluginName);
  paths.push_back(std::filesystem::path(SNELL_PLUGIN_DIR) / kPluginName);
  return paths;
}

LoadResult load() {
  LoadResult result;
  for (const auto& path : candidates()) {
    if (!std::filesystem::exists(path)) continue;
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      result.error = dlerror();
      continue;
    }
    result.backend.write = reinterpret_cast<SnellOiioWrite>(dlsym(handle, "snell_oiio_write"));
    result.backend.read = reinterpret_cast<SnellOiioRead>(dlsym(handle, "snell_oiio_read"));
    result.backend.free = reinterpret_cast<SnellOiioFree>(dlsym(handle, "snell_oiio_free"));
    result.backend.write_channels =
        reinterpret_cast<SnellOiioWriteChannels>(dlsym(handle, "snell_oiio_write_channels"));
    if (result.backend.write && result.backend.read && result.backend.free) {
      result.error.clear();
      return result;
    }
    result.error = path.string() + " lacks the snell_oiio_* entry points";
  }
  if (result.error.empty()) result.error = std::string(kPluginName) + " not found beside the program";
  result.backend = {};
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
