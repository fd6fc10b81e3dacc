#include "cli/checkpoint.hpp"

#include <fmt/core.h>

#include <cstdio>
#include <system_error>

#include "snell/io/image_file.hpp"
#include "snell/render/resume_file.hpp"

namespace snell::cli {

std::filesystem::path resume_path(const std::filesystem::path& output) {
  std::filesystem::path p = output;
  p += ".snell-resume";
  return p;
}

Checkpoint::Checkpoint(std::filesystem::path path, uint64_t fingerprint, const io::Image& image,
                       std::vector<render::Tile> done, double interval_seconds)
    : path_(std::move(path)),
      fingerprint_(fingerprint),
      image_(image),
      done_(std::move(done)),
      interval_(interval_seconds),
      last_save_(std::chrono::steady_clock::now()) {}

void Checkpoint::tile_done(const render::Tile& tile) {
  std::lock_guard lock(mutex_);
  done_.push_back(tile);
  if (interval_ <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_save_).count() < interval_) return;
  // A failed periodic checkpoint must not end a render that can still finish: warn and go on.
  try {
    save_locked();
  } catch (const render::ResumeError& e) {
    fmt::print(stderr, "snell: warning: {}\n", e.what());
  }
  last_save_ = now;
}

void Checkpoint::save() {
  std::lock_guard lock(mutex_);
  // A resume file that cannot be written is an output error (exit code 3), like an image.
  try {
    save_locked();
  } catch (const render::ResumeError& e) {
    throw io::ImageIoError(e.what());
  }
}

// Only finished tiles' pixels are read; workers write other tiles meanwhile, never these.
void Checkpoint::save_locked() {
  render::write_resume_file(path_, fingerprint_, image_, done_);
}

void Checkpoint::remove() const {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

}  // namespace snell::cli
