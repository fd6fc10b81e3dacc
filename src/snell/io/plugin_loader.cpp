#include "snell/io/plugin_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <vector>

namespace snell::io {

namespace {

std::vector<std::filesystem::path> candidates(const char* file_name) {
  std::vector<std::filesystem::path> paths;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back(exe.parent_path() / file_name);
  paths.push_back(std::filesystem::path(SNELL_PLUGIN_DIR) / file_name);
  return paths;
}

}  // namespace

void* open_plugin(const char* file_name, std::string& error) {
  error.clear();
  for (const auto& path : candidates(file_name)) {
    if (!std::filesystem::exists(path)) continue;
    if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
      error.clear();
      return handle;
    }
    const char* why = dlerror();
    error = why ? why : "dlopen failed";
  }
  if (error.empty()) error = std::string(file_name) + " not found beside the program";
  return nullptr;
}

void* plugin_symbol(void* handle, const char* name) {
  return handle ? dlsym(handle, name) : nullptr;
}

}  // namespace snell::io
