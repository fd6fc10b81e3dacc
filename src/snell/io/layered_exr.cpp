#include "snell/io/layered_exr.hpp"

#include <unistd.h>

#include "snell/io/image_backend.hpp"
#include "snell/io/image_file.hpp"

namespace snell::io {

namespace fs = std::filesystem;

void write_layered_exr(const fs::path& path, int width, int height, const std::vector<std::string>& names,
                       const std::vector<float>& pixels) {
  const ImageBackend& backend = image_backend();
  if (!backend.write_channels)
    throw ImageIoError("cannot write '" + path.string() + "': the image plugin is too old");
  if (pixels.size() != static_cast<size_t>(width) * height * names.size())
    throw ImageIoError("cannot write '" + path.string() + "': channel data does not match the size");
  std::vector<const char*> c_names;
  for (const std::string& n : names) c_names.push_back(n.c_str());
  fs::path temp = path;
  temp += ".tmp" + std::to_string(getpid()) + ".exr";
  char message[512] = {};
  std::error_code ec;
  if (backend.write_channels(temp.c_str(), width, height, static_cast<int>(names.size()), c_names.data(),
                             pixels.data(), message, sizeof message) != 0) {
    fs::remove(temp, ec);
    throw ImageIoError("cannot write '" + path.string() + "': " + (message[0] ? message : "unknown error"));
  }
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw ImageIoError("cannot write '" + path.string() + "': " + ec.message());
  }
}

}  // namespace snell::io
