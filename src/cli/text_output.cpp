#include "cli/text_output.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

#include "cli/options.hpp"
#include "snell/io/image_file.hpp"

namespace snell::cli {

namespace fs = std::filesystem;

namespace {

fs::path temp_beside(const fs::path& path) {
  fs::path temp = path;
  temp += fmt::format(".tmp{}", getpid());
  return temp;
}

}  // namespace

void check_writable(const fs::path& path, const char* what) {
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw UsageError(fmt::format("{} {}: folder {} does not exist", what, path.string(), folder.string()));
  if (fs::is_directory(path, ec)) throw UsageError(fmt::format("{} {}: is a folder", what, path.string()));
  if (access(folder.c_str(), W_OK) != 0)
    throw UsageError(fmt::format("{} {}: folder {} is not writable", what, path.string(), folder.string()));
}

void write_text_file(const fs::path& path, const std::string& text) {
  const fs::path temp = temp_beside(path);
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) throw io::ImageIoError(fmt::format("cannot write {}", path.string()));
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok) {
    fs::remove(temp);
    throw io::ImageIoError(fmt::format("cannot write {}", path.string()));
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp);
    throw io::ImageIoError(fmt::format("cannot write {}: {}", path.string(), ec.message()));
  }
}

}  // namespace snell::cli
